// The importance of a light tree node at a shading point (shaders/shared/light_tree.h):
// a bound on what its lights may send there and an estimate of it, from the node's
// bounding sphere, summed intensity and orientation cone (pbrt-v4's LightBounds::Importance,
// with Cycles' reason for an estimate beside the bound). Four nodes at once for the walk,
// which weighs a node's grandchildren together; on the CPU in SSE2 lanes.
//
// Scene access (backend_contract.h): VKPT_LIGHT_NODE(i).
#ifndef VKPT_LIGHT_IMPORTANCE_H
#define VKPT_LIGHT_IMPORTANCE_H
#include "prelude.h"  // first, as in every shared header

#include "layout.h"

#if defined(__cplusplus) && defined(__SSE2__)
#include <emmintrin.h>
#endif

VKPT_BEGIN_NAMESPACE
// cos(max(0, θa − θb)) and sin(max(0, θa − θb)) from the sines and cosines of two angles
// in [0, π] (pbrt-v4's LightBounds::Importance).
VKPT_FN float CosSubClamped(float sinA, float cosA, float sinB, float cosB) {
  return cosA > cosB ? 1.0f : cosA * cosB + sinA * sinB;
}

VKPT_FN float SinSubClamped(float sinA, float cosA, float sinB, float cosB) {
  return cosA > cosB ? 0.0f : sinA * cosB - cosA * sinB;
}

// What the lights of `node` may contribute at point p of a surface with unit normal n
// (n = 0: no surface), twice:
//  x: a bound: their intensity times the largest cosine any of their emission directions
//     may make with the direction to p, over the squared distance to the bounding
//     sphere's centre (at least its squared radius and 1e-12, so that a point among the
//     lights, or at a point light, does not make it infinite), times the largest cosine a direction to the sphere may
//     make with n. 0 only where no light of the node can reach p.
//  y: an estimate: the same as if all the lights sat at the sphere's centre (no widening
//     by the angle the sphere subtends; the distance only kept from 0), and 0 where x is.
// The bound alone undervalues a node p is close to, whose lights it sees at wide angles
// (Cycles' light tree mixes a bound with an estimate for the same reason). A seam.
#ifndef LightNodeImportance
VKPT_FN vec2 LightNodeImportance(LightTreeNode node, vec3 p, vec3 n) {
  vec3 d = p - node.center;
  float d2 = dot(d, d);
  float r2 = node.radius * node.radius;
  float invDist = d2 > 0.0f ? 1.0f / sqrt(d2) : 0.0f;
  vec3 wi = d2 > 0.0f ? d * invDist : vec3(0.0f, 0.0f, 1.0f);  // from the lights towards p
  // The half-angle θb under which p sees the sphere (sin θb = r/d): every direction from
  // inside it.
  bool outside = d2 > r2;
  float sinB = outside ? node.radius * invDist : 0.0f;
  float cosB = outside ? sqrt(max(0.0f, 1.0f - sinB * sinB)) : -1.0f;
  float cosW = dot(node.axis, wi);
  if ((node.split & kLightNodeTwoSided) != 0u) cosW = abs(cosW);
  float sinW = sqrt(max(0.0f, 1.0f - cosW * cosW));
  // θ' = max(0, θw − θo − θb): the smallest angle between an emission direction and a
  // direction from the sphere to p.
  float cosX = CosSubClamped(sinW, cosW, node.sinThetaO, node.cosThetaO);
  float sinX = SinSubClamped(sinW, cosW, node.sinThetaO, node.cosThetaO);
  float cosP = CosSubClamped(sinX, cosX, sinB, cosB);
  if (cosP <= node.cosThetaE) return vec2(0.0f);
  float near2 = max(d2, 1e-12f);  // keeps a point at a point light finite
  float importance = node.intensity * cosP / max(near2, r2);
  float estimate = node.intensity * max(cosX, 0.0f) / max(near2, 0.01f * r2);
  if (n != vec3(0.0f)) {  // both sides: light may arrive through a transmissive surface
    float cosI = abs(dot(wi, n));
    float sinI = sqrt(max(0.0f, 1.0f - cosI * cosI));
    importance *= CosSubClamped(sinI, cosI, sinB, cosB);
    estimate *= cosI;
  }
  return importance > 0.0f ? vec2(importance, estimate) : vec2(0.0f);
}
#endif

// LightNodeImportance of four nodes (kInvalidIndex: none, importance 0): bounds in
// `bound`, estimates in `estimate`, lane by lane.
struct LightImportances {
  vec4 bound;
  vec4 estimate;
};

#if defined(__cplusplus) && defined(__SSE2__)
// On the CPU the four lanes run in SSE2 registers: the same operations in the same order
// as LightNodeImportance, each correctly rounded, so the same results (up to the sign of a
// zero), at a quarter of the instructions and without its branches.
inline __m128 Select(__m128 mask, __m128 a, __m128 b) { return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b)); }
inline __m128 CosSubClamped4(__m128 sinA, __m128 cosA, __m128 sinB, __m128 cosB) {
  __m128 sub = _mm_add_ps(_mm_mul_ps(cosA, cosB), _mm_mul_ps(sinA, sinB));
  return Select(_mm_cmpgt_ps(cosA, cosB), _mm_set1_ps(1.0f), sub);
}
inline __m128 SinSubClamped4(__m128 sinA, __m128 cosA, __m128 sinB, __m128 cosB) {
  __m128 sub = _mm_sub_ps(_mm_mul_ps(sinA, cosB), _mm_mul_ps(cosA, sinB));
  return _mm_andnot_ps(_mm_cmpgt_ps(cosA, cosB), sub);
}
// sqrt(max(0, 1 − c²)): glm's max(0, x) is x where 0 < x, else 0, as _mm_max_ps(x, 0).
inline __m128 SinOfCos4(__m128 c) {
  return _mm_sqrt_ps(_mm_max_ps(_mm_sub_ps(_mm_set1_ps(1.0f), _mm_mul_ps(c, c)), _mm_setzero_ps()));
}
inline __m128 Abs4(__m128 x) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), x); }

inline LightImportances LightNodeImportances(VKPT_SCENE_PARAM uvec4 nodes, vec3 p, vec3 n) {
  // The nodes' three rows (center, radius; axis, intensity; cones, split) transposed.
  uint first = nodes.x;
  __m128 rows[3][4];
  for (int lane = 0; lane < 4; ++lane) {
    const float* node = &VKPT_LIGHT_NODE(nodes[lane] == kInvalidIndex ? first : nodes[lane]).center.x;
    for (int row = 0; row < 3; ++row) rows[row][lane] = _mm_loadu_ps(node + 4 * row);
  }
  for (auto& row : rows) _MM_TRANSPOSE4_PS(row[0], row[1], row[2], row[3]);
  const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f);
  const __m128 radius = rows[0][3], intensity = rows[1][3];
  const __m128 cosO = rows[2][0], sinO = rows[2][1], cosE = rows[2][2];
  const __m128 twoSided = _mm_castsi128_ps(_mm_srai_epi32(_mm_castps_si128(rows[2][3]), 31));
  __m128 dx = _mm_sub_ps(_mm_set1_ps(p.x), rows[0][0]);
  __m128 dy = _mm_sub_ps(_mm_set1_ps(p.y), rows[0][1]);
  __m128 dz = _mm_sub_ps(_mm_set1_ps(p.z), rows[0][2]);
  __m128 d2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
  __m128 r2 = _mm_mul_ps(radius, radius);
  __m128 away = _mm_cmpgt_ps(d2, zero);
  __m128 invDist = _mm_and_ps(away, _mm_div_ps(one, _mm_sqrt_ps(d2)));
  __m128 wx = _mm_and_ps(away, _mm_mul_ps(dx, invDist));
  __m128 wy = _mm_and_ps(away, _mm_mul_ps(dy, invDist));
  __m128 wz = Select(away, _mm_mul_ps(dz, invDist), one);
  __m128 outside = _mm_cmpgt_ps(d2, r2);
  __m128 sinB = _mm_and_ps(outside, _mm_mul_ps(radius, invDist));
  __m128 cosB = Select(outside, SinOfCos4(sinB), _mm_set1_ps(-1.0f));
  __m128 cosW =
      _mm_add_ps(_mm_add_ps(_mm_mul_ps(rows[1][0], wx), _mm_mul_ps(rows[1][1], wy)), _mm_mul_ps(rows[1][2], wz));
  cosW = Select(twoSided, Abs4(cosW), cosW);
  __m128 sinW = SinOfCos4(cosW);
  __m128 cosX = CosSubClamped4(sinW, cosW, sinO, cosO);
  __m128 sinX = SinSubClamped4(sinW, cosW, sinO, cosO);
  __m128 cosP = CosSubClamped4(sinX, cosX, sinB, cosB);
  __m128 near2 = _mm_max_ps(_mm_set1_ps(1e-12f), d2);
  __m128 importance = _mm_div_ps(_mm_mul_ps(intensity, cosP), _mm_max_ps(r2, near2));
  __m128 estimate =
      _mm_div_ps(_mm_mul_ps(intensity, _mm_max_ps(zero, cosX)), _mm_max_ps(_mm_mul_ps(_mm_set1_ps(0.01f), r2), near2));
  if (n != vec3(0.0f)) {
    __m128 cosI = Abs4(_mm_add_ps(_mm_add_ps(_mm_mul_ps(wx, _mm_set1_ps(n.x)), _mm_mul_ps(wy, _mm_set1_ps(n.y))),
                                  _mm_mul_ps(wz, _mm_set1_ps(n.z))));
    importance = _mm_mul_ps(importance, CosSubClamped4(SinOfCos4(cosI), cosI, sinB, cosB));
    estimate = _mm_mul_ps(estimate, cosI);
  }
  __m128 valid = _mm_castsi128_ps(_mm_cmpeq_epi32(_mm_setr_epi32(nodes.x == kInvalidIndex, nodes.y == kInvalidIndex,
                                                                 nodes.z == kInvalidIndex, nodes.w == kInvalidIndex),
                                                  _mm_setzero_si128()));
  __m128 keep = _mm_and_ps(valid, _mm_and_ps(_mm_cmpgt_ps(cosP, cosE), _mm_cmpgt_ps(importance, zero)));
  LightImportances r;
  _mm_storeu_ps(&r.bound.x, _mm_and_ps(keep, importance));
  _mm_storeu_ps(&r.estimate.x, _mm_and_ps(keep, estimate));
  return r;
}
#else
VKPT_FN vec2 LightNodeImportanceOrNone(VKPT_SCENE_PARAM uint i, vec3 p, vec3 n) {
  return i == kInvalidIndex ? vec2(0.0f) : LightNodeImportance(VKPT_LIGHT_NODE(i), p, n);
}

VKPT_FN LightImportances LightNodeImportances(VKPT_SCENE_PARAM uvec4 nodes, vec3 p, vec3 n) {
  vec2 a = LightNodeImportanceOrNone(VKPT_SCENE_ARG nodes.x, p, n);
  vec2 b = LightNodeImportanceOrNone(VKPT_SCENE_ARG nodes.y, p, n);
  vec2 c = LightNodeImportanceOrNone(VKPT_SCENE_ARG nodes.z, p, n);
  vec2 d = LightNodeImportanceOrNone(VKPT_SCENE_ARG nodes.w, p, n);
  LightImportances r;
  r.bound = vec4(a.x, b.x, c.x, d.x);
  r.estimate = vec4(a.y, b.y, c.y, d.y);
  return r;
}
#endif

VKPT_END_NAMESPACE

#endif

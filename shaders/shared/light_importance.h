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

VKPT_FN vec2 LightNodeImportanceOrNone(VKPT_SCENE_PARAM uint i, vec3 p, vec3 n) {
  return i == kInvalidIndex ? vec2(0.0f) : LightNodeImportance(VKPT_LIGHT_NODE(i), p, n);
}

VKPT_FN LightImportances LightNodeImportancesEach(VKPT_SCENE_PARAM uvec4 nodes, vec3 p, vec3 n) {
  vec2 a = LightNodeImportanceOrNone(VKPT_SCENE_ARG nodes.x, p, n);
  vec2 b = LightNodeImportanceOrNone(VKPT_SCENE_ARG nodes.y, p, n);
  vec2 c = LightNodeImportanceOrNone(VKPT_SCENE_ARG nodes.z, p, n);
  vec2 d = LightNodeImportanceOrNone(VKPT_SCENE_ARG nodes.w, p, n);
  LightImportances r;
  r.bound = vec4(a.x, b.x, c.x, d.x);
  r.estimate = vec4(a.y, b.y, c.y, d.y);
  return r;
}

VKPT_END_NAMESPACE

#endif

// The light tree: choosing one of many finite lights (emissive triangles, point and spot
// lights) by how much each may light the shading point, not by its power alone (Conty
// Estevez and Kulla 2018, "Importance Sampling of Many Lights with Adaptive Tree
// Splitting"; pbrt-v4's BVHLightSampler). Each node of a binary tree over the lights bounds
// where they are (a sphere), how strongly they emit (the sum of their greatest radiant
// intensities) and which way (a cone of normals θo wide, emitting up to θe beyond it). A
// sample walks from the root and picks a child with probability ∝ the importance at the
// shading point of the child's own children (of the child itself if it is a leaf): the
// four grandchildren of a node are evaluated together, and the walk takes two levels at
// a time. The light's pmf, the product of its ancestors' choices, is what LightTreePmf
// recomputes for multiple importance sampling.
//
// The host builds the tree (host/render/light_tree.h) and orders the light table so that
// node i over lights [first, end) has its left child at i + 1 and its right child, over
// lights [split, end), at i + 2 (split − first): no child index or trail is stored.
//
// Scene access (backend_contract.h): VKPT_LIGHT_NODE(i); VKPT_LIGHT_TREE tells whether the
// scene has a tree.
#ifndef VKPT_LIGHT_TREE_H
#define VKPT_LIGHT_TREE_H
#include "prelude.h"  // first, as in every shared header

#include "layout.h"
#include "sampling.h"

#if defined(__cplusplus) && defined(__SSE2__)
#include <emmintrin.h>
#endif

// A shader may define VKPT_LIGHT_TREE as a specialization constant that is false for a
// scene without a tree, so that lavapipe compiles none of its code.
#ifndef VKPT_LIGHT_TREE
#define VKPT_LIGHT_TREE true
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

// The probability of choosing lights of importance `a` (LightNodeImportance, or a sum of
// them) over lights of importance `b`: the mean of the choices ∝ bound and ∝ estimate (∝
// bound alone when neither has an estimate; ½ when neither may light the point, whose
// lights then contribute 0). Positive wherever a's bound is: a light that may light the
// point can be chosen.
VKPT_FN float ChoiceProbability(vec2 a, vec2 b) {
  float pBound = a.x + b.x > 0.0f ? a.x / (a.x + b.x) : 0.5f;
  return a.y + b.y > 0.0f ? 0.5f * (pBound + a.y / (a.y + b.y)) : pBound;
}

// A walk down the tree: the node reached, its lights [first, end), and the interval
// [lo, hi) of the random number u ∈ [0,1) that leads to it. Each choice divides the
// interval between two sides in proportion to their probabilities, so a light's pmf is
// its leaf's interval's width, the very measure of the u that choose it (multiplied
// probabilities, or u stretched back to [0,1) at each level as pbrt-v4 does, drift from
// what float u really pick once a few levels have small probabilities).
struct LightTreeWalk {
  uint node;
  uint first;
  uint end;
  float lo;
  float hi;
};

// The walk at the root of a tree over `count` lights chosen for u ∈ [0, share).
VKPT_FN LightTreeWalk StartLightTreeWalk(uint count, float share) {
  LightTreeWalk w;
  w.node = 0u;
  w.first = 0u;
  w.end = count;
  w.lo = 0.0f;
  w.hi = share;
  return w;
}

// The first light of node i's right child (node i over lights [first, end), end − first
// ≥ 2), and that child's index: the left one is i + 1.
VKPT_FN uint LightNodeSplit(VKPT_SCENE_PARAM uint i) { return VKPT_LIGHT_NODE(i).split & ~kLightNodeTwoSided; }

VKPT_FN uint RightLightNode(uint i, uint first, uint split) { return i + 2u * (split - first); }

// Moves the walk to the left child (node `left`, lights [first, split)) with probability
// pl, else to the right one: towards light k, or where u falls (k = kInvalidIndex).
// leftMay, rightMay: whether each side may light the point.
VKPT_FN void ChooseLightChild(VKPT_INOUT(LightTreeWalk) w, uint left, uint right, uint split, float pl, bool leftMay,
                              bool rightMay, float u, uint k) {
  VKPT_PRECISE float m = w.lo + (w.hi - w.lo) * pl;
  // A side that may light the point keeps an interval of positive width (a float step at
  // least), even where its share rounds to nothing, so that it stays reachable while the
  // interval is two steps wide.
  float least = w.lo > 1e-30f ? uintBitsToFloat(floatBitsToUint(w.lo) + 1u) : w.lo + 1e-30f;
  float most = uintBitsToFloat(floatBitsToUint(w.hi) - 1u);
  if (least <= most) m = clamp(m, leftMay ? least : w.lo, rightMay ? most : w.hi);
  // Selects rather than branches: the choice is a coin flip no predictor foresees.
  bool toLeft = k == kInvalidIndex ? u < m : k < split;
  w.node = toLeft ? left : right;
  w.first = toLeft ? w.first : split;
  w.end = toLeft ? split : w.end;
  w.lo = toLeft ? w.lo : m;
  w.hi = toLeft ? m : w.hi;
}

// Two levels down towards the light u picks (k = kInvalidIndex), or towards light k; one
// where the child reached is a leaf. The child is chosen by the importance of its own
// children (of itself if a leaf), which bound its lights more tightly than it does, and
// all four are evaluated together: the walk takes half as many dependent steps.
VKPT_FN void DescendLightTree(VKPT_SCENE_PARAM VKPT_INOUT(LightTreeWalk) w, vec3 p, vec3 n, float u, uint k) {
  uint split = LightNodeSplit(VKPT_SCENE_ARG w.node);
  uint left = w.node + 1u;
  uint right = RightLightNode(w.node, w.first, split);
  bool leftLeaf = split - w.first == 1u;
  bool rightLeaf = w.end - split == 1u;
  uint leftSplit = leftLeaf ? split : LightNodeSplit(VKPT_SCENE_ARG left);
  uint rightSplit = rightLeaf ? w.end : LightNodeSplit(VKPT_SCENE_ARG right);
  // Each child's candidates: its children, or itself as the first with none beside it.
  uvec4 candidates =
      uvec4(leftLeaf ? left : left + 1u, leftLeaf ? kInvalidIndex : RightLightNode(left, w.first, leftSplit),
            rightLeaf ? right : right + 1u, rightLeaf ? kInvalidIndex : RightLightNode(right, split, rightSplit));
  LightImportances imp = LightNodeImportances(VKPT_SCENE_ARG candidates, p, n);
  vec2 leftA = vec2(imp.bound.x, imp.estimate.x);
  vec2 leftB = vec2(imp.bound.y, imp.estimate.y);
  vec2 rightA = vec2(imp.bound.z, imp.estimate.z);
  vec2 rightB = vec2(imp.bound.w, imp.estimate.w);
  // Both second choices are worked out before the first is made, which they then follow.
  float pLeft = ChoiceProbability(leftA + leftB, rightA + rightB);
  float pLeftA = ChoiceProbability(leftA, leftB);
  float pRightA = ChoiceProbability(rightA, rightB);
  ChooseLightChild(w, left, right, split, pLeft, leftA.x + leftB.x > 0.0f, rightA.x + rightB.x > 0.0f, u, k);
  if (w.end - w.first > 1u) {
    bool wentLeft = w.node == left;
    uint childSplit = wentLeft ? leftSplit : rightSplit;
    ChooseLightChild(w, w.node + 1u, RightLightNode(w.node, w.first, childSplit), childSplit,
                     wentLeft ? pLeftA : pRightA, (wentLeft ? leftA.x : rightA.x) > 0.0f,
                     (wentLeft ? leftB.x : rightB.x) > 0.0f, u, k);
  }
}

struct LightTreeChoice {
  uint light;  // in [0, count)
  float pmf;   // share × the tree's probability
  float u;     // the random number, stretched back to [0,1) within the choice
};

// Picks one of the tree's `count` lights for p, n with u ∈ [0, share) (the tree's share
// of the light table), descending at most the tree's depth (FrameParams::treeDepth) levels.
VKPT_FN LightTreeChoice SampleLightTree(VKPT_SCENE_PARAM uint count, float share, vec3 p, vec3 n, float u) {
  LightTreeWalk w = StartLightTreeWalk(count, share);
  while (w.end - w.first > 1u) DescendLightTree(VKPT_SCENE_ARG w, p, n, u, kInvalidIndex);
  LightTreeChoice c;
  c.light = w.first;
  c.pmf = w.hi - w.lo;
  c.u = c.pmf > 0.0f ? min((u - w.lo) / c.pmf, kOneMinusEpsilon) : 0.0f;
  return c;
}

// The probability that SampleLightTree(count, share) picks light k at p, n.
VKPT_FN float LightTreePmf(VKPT_SCENE_PARAM uint count, float share, vec3 p, vec3 n, uint k) {
  LightTreeWalk w = StartLightTreeWalk(count, share);
  while (w.end - w.first > 1u) DescendLightTree(VKPT_SCENE_ARG w, p, n, 0.0f, k);
  return w.hi - w.lo;
}

VKPT_END_NAMESPACE

#endif

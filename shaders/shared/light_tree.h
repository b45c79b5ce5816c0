// The light tree: choosing one of many finite lights (emissive triangles, point and spot
// lights) by how much each may light the shading point, not by its power alone (Conty
// Estevez and Kulla 2018, "Importance Sampling of Many Lights with Adaptive Tree
// Splitting"; pbrt-v4's BVHLightSampler). Each node of a binary tree over the lights bounds
// where they are (a sphere), how strongly they emit (the sum of their greatest radiant
// intensities) and which way (a cone of normals θo wide, emitting up to θe beyond it). A
// sample walks from the root and picks a child with probability ∝ its importance at the
// shading point; the light's pmf, the product of its ancestors' choices, is what
// LightTreePmf recomputes for multiple importance sampling.
//
// The host builds the tree (host/render/light_tree.h) and orders the light table so that
// node i over lights [first, end) has its left child at i + 1 and its right child, over
// lights [split, end), at i + 2 (split − first): no child index or trail is stored.
//
// Scene access (backend_contract.h): VKPT_LIGHT_NODE(i); VKPT_LIGHT_TREE tells whether the
// scene has a tree.
#ifndef VKPT_LIGHT_TREE_H
#define VKPT_LIGHT_TREE_H
#include "layout.h"
#include "prelude.h"
#include "sampling.h"

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
//     sphere's centre (at least its squared radius, so that a point among the lights
//     does not make it infinite), times the largest cosine a direction to the sphere may
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
  float importance = node.intensity * cosP / max(d2, r2);
  float estimate = node.intensity * max(cosX, 0.0f) / max(d2, 0.01f * r2);
  if (n != vec3(0.0f)) {  // both sides: light may arrive through a transmissive surface
    float cosI = abs(dot(wi, n));
    float sinI = sqrt(max(0.0f, 1.0f - cosI * cosI));
    importance *= CosSubClamped(sinI, cosI, sinB, cosB);
    estimate *= cosI;
  }
  return importance > 0.0f ? vec2(importance, estimate) : vec2(0.0f);
}
#endif

// The probability of the left child of a node whose children are at `left` and `right`,
// at p, n: the mean of the choices ∝ bound and ∝ estimate (∝ bound alone when neither
// child has an estimate; ½ each when neither may light p, whose lights then contribute
// 0). Positive wherever the left child's bound is: a light that may light p can be chosen.
VKPT_FN float LeftChildProbability(VKPT_SCENE_PARAM uint left, uint right, vec3 p, vec3 n) {
  vec2 l = LightNodeImportance(VKPT_LIGHT_NODE(left), p, n);
  vec2 r = LightNodeImportance(VKPT_LIGHT_NODE(right), p, n);
  float pBound = l.x + r.x > 0.0f ? l.x / (l.x + r.x) : 0.5f;
  return l.y + r.y > 0.0f ? 0.5f * (pBound + l.y / (l.y + r.y)) : pBound;
}

// A walk down the tree: the node reached, its lights [first, end), and the interval
// [lo, hi) of the random number u ∈ [0,1) that leads to it. Each node divides its
// interval between its children in proportion to their probabilities, so a light's pmf
// is its leaf's interval's width, the very measure of the u that choose it (multiplied
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

// One level down towards the light u picks (k = kInvalidIndex), or towards light k.
VKPT_FN void DescendLightTree(VKPT_SCENE_PARAM VKPT_INOUT(LightTreeWalk) w, vec3 p, vec3 n, float u, uint k) {
  uint split = VKPT_LIGHT_NODE(w.node).split & ~kLightNodeTwoSided;
  uint right = w.node + 2u * (split - w.first);
  float pl = LeftChildProbability(VKPT_SCENE_ARG w.node + 1u, right, p, n);
  VKPT_PRECISE float m = w.lo + (w.hi - w.lo) * pl;
  // A child of positive probability keeps an interval of positive width (a float step at
  // least), even where its share rounds to nothing, so that it stays reachable.
  VKPT_PRECISE float least = w.lo + max(w.lo * 1.1920929e-7f, 1e-30f);
  VKPT_PRECISE float most = w.hi - w.hi * 1.1920929e-7f;
  if (least < most) m = clamp(m, pl > 0.0f ? least : w.lo, pl < 1.0f ? most : w.hi);
  // Selects rather than branches: the choice is a coin flip no predictor foresees.
  bool left = k == kInvalidIndex ? u < m : k < split;
  w.node = left ? w.node + 1u : right;
  w.first = left ? w.first : split;
  w.end = left ? split : w.end;
  w.lo = left ? w.lo : m;
  w.hi = left ? m : w.hi;
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

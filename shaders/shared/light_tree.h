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
#include "light_importance.h"
#include "sampling.h"

// A shader may define VKPT_LIGHT_TREE as a specialization constant that is false for a
// scene without a tree, so that lavapipe compiles none of its code.
#ifndef VKPT_LIGHT_TREE
#define VKPT_LIGHT_TREE true
#endif
// A backend may compute the four importances of a step its own way (the CPU in SSE2
// lanes, cpu/light_importances_sse2.h), with the same results.
#ifndef VKPT_LIGHT_IMPORTANCES
#define VKPT_LIGHT_IMPORTANCES(nodes, p, n) LightNodeImportancesEach(VKPT_SCENE_ARG nodes, p, n)
#endif

VKPT_BEGIN_NAMESPACE

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
  LightImportances imp = VKPT_LIGHT_IMPORTANCES(candidates, p, n);
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

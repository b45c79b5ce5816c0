// Stackless BVH traversal for GLSL, over the depth-first skip-link layout (Smits 1998,
// "Efficiency Issues for Ray Tracing"). The including shader enables
// GL_KHR_shader_subgroup_basic and GL_KHR_shader_subgroup_arithmetic; the scene comes
// from scene_fetch.glsl.
//
// A node whose box is hit before the closest hit so far is entered by stepping to the
// next node; a missed box or a finished leaf jumps to its skip link. No stack: no
// per-invocation memory and no divergence in stack depth between SIMD lanes.
//
// Node visits and triangle tests share ONE loop. Besides keeping lanes in step, this
// makes the work countable: lavapipe (Mesa's gallivm) silently ends any shader after
// 65535 loop iterations in total, counted per SIMD group, so pathtrace.comp must know
// how many it has used (gLoopIterations) to flag a sample that may have been cut short.
#ifndef VKPT_TRAVERSE_GLSL
#define VKPT_TRAVERSE_GLSL
#include "shared/layout.h"
#include "shared/intersect.h"
#include "scene_fetch.glsl"

// Set by the including shader's main(): nodes per copy of the tree, and the number of
// copies (1, or 8 ordered near-first for each octant of ray directions).
uint gNodeCount = 0u;
uint gNodeCopies = 1u;

// The root of the tree copy ordered for this ray direction's octant.
uint RootFor(vec3 dir) {
  if (gNodeCopies == 1u) return 0u;
  uint octant = (dir.x < 0.0f ? 1u : 0u) | (dir.y < 0.0f ? 2u : 0u) | (dir.z < 0.0f ? 4u : 0u);
  return octant * gNodeCount;
}

// Loop iterations this SIMD group has run in traversal loops, held by one lane per
// loop execution (the elected one), so a subgroupAdd over the group gives the total.
uint gLoopIterations = 0u;

// All active lanes run the loop together until the last one is done: the group spends
// max(lane iterations) + 1 (the final exit test).
void CountLoop(uint laneIterations) {
  uint groupIterations = subgroupMax(laneIterations) + 1u;
  if (subgroupElect()) gLoopIterations += groupIterations;
}

// One step of the walk at node i: a missed box (or one beyond tMax) jumps to its skip
// link, an inner node descends to its first child, a leaf queues its triangles [k, end)
// and moves on to its skip link.
void VisitNode(vec3 origin, vec3 invDir, float tMax, inout uint i, inout uint k, inout uint end) {
  BvhNode node = FetchNode(i);
  if (IntersectBox(node.lo, node.hi, origin, invDir, tMax) < 0.0f) {
    i = node.skip;
  } else if (node.leaf == 0u) {
    i = i + 1u;
  } else {
    k = node.leaf >> 4u;
    end = k + (node.leaf & 15u);
    i = node.skip;
  }
}

HitRecord TraceClosest(vec3 origin, vec3 dir, float tMax) {
  HitRecord hit;
  hit.t = -1.0f;
  hit.b1 = 0.0f;
  hit.b2 = 0.0f;
  hit.triangle = kInvalidIndex;
  vec3 invDir = SafeInverse(dir);
  uint i = RootFor(dir);  // next node
  uint k = 0u;      // next triangle of the current leaf
  uint end = 0u;    // one past the current leaf's last triangle
  uint steps = 0u;
  while (k < end || i != kInvalidIndex) {
    ++steps;
    if (k < end) {
      Triangle t = FetchTriangle(k);
      vec3 r = IntersectTriangle(t.v0, t.e1, t.e2, origin, dir, tMax);
      if (r.x >= 0.0f) {
        tMax = r.x;
        hit.t = r.x;
        hit.b1 = r.y;
        hit.b2 = r.z;
        hit.triangle = k;
      }
      ++k;
      continue;
    }
    VisitNode(origin, invDir, tMax, i, k, end);
  }
  CountLoop(steps);
  return hit;
}

// Any hit with t ∈ (0, tMax): the walk stops at the first one.
bool TraceOccluded(vec3 origin, vec3 dir, float tMax) {
  vec3 invDir = SafeInverse(dir);
  uint i = RootFor(dir);
  uint k = 0u;
  uint end = 0u;
  uint steps = 0u;
  bool occluded = false;
  while (k < end || i != kInvalidIndex) {
    ++steps;
    if (k < end) {
      Triangle t = FetchTriangle(k);
      if (IntersectTriangle(t.v0, t.e1, t.e2, origin, dir, tMax).x >= 0.0f) {
        occluded = true;
        break;
      }
      ++k;
      continue;
    }
    VisitNode(origin, invDir, tMax, i, k, end);
  }
  CountLoop(steps);
  return occluded;
}

#endif

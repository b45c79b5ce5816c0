// Stackless BVH traversal for GLSL, over the depth-first skip-link layout (Smits 1998,
// "Efficiency Issues for Ray Tracing"). The including shader enables
// GL_KHR_shader_subgroup_basic and GL_KHR_shader_subgroup_arithmetic; the scene comes
// from scene_fetch.glsl.
//
// A node whose box is hit before the closest hit so far is entered by stepping to the
// next node; a missed box or a finished leaf jumps to its skip link. No stack: no
// per-invocation memory and no divergence in stack depth between SIMD lanes.
//
// The loops count their passes: lavapipe (Mesa's gallivm) silently ends any shader after
// 65535 loop passes in total, counted per SIMD group, so pathtrace.comp must know how many
// it has used (gLoopIterations) to flag a sample that may have been cut short.
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

// Loop passes this SIMD group has run in traversal loops, held by the lanes elected to
// count them, so a subgroupAdd over the group gives the total. gallivm keeps one counter
// per shader invocation (per SIMD group), decremented at the end of every pass of any
// loop. It runs a loop's body masked and leaves the loop only at the end of a pass in
// which no lane is left: a while loop makes one pass per iteration of its slowest lane
// plus a last, fully masked pass in which every lane leaves; a do-while loop ends with
// its slowest lane's last iteration (one masked pass if no lane has anything to do).
// gallivm also never branches around an if: its body runs masked even when no lane
// takes it, so that last pass of a while loop costs a whole body. The traversal loops
// are therefore do-while loops (docs/design-notes.md, "Shader traversal loops").
// GpuTest.TraversalCountsLoopPassesExactly checks this count against the limit itself.
uint gLoopIterations = 0u;

void CountPasses(uint passes) {
  if (subgroupElect()) gLoopIterations += passes;
}

// Boxes this lane has tested, for the heat map AOV (aov.comp), in shaders that define
// VKPT_COUNT_BOX_TESTS: one per node visited.
#ifdef VKPT_COUNT_BOX_TESTS
uint gBoxTests = 0u;
#endif

// One pass of the outer do-while loop holding two inner ones, in which this lane ran
// its inner loops' bodies nodeSteps and triangleSteps times.
void CountNestedPass(uint nodeSteps, uint triangleSteps) {
  CountPasses(1u + max(subgroupMax(nodeSteps), 1u) + max(subgroupMax(triangleSteps), 1u));
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

// Visits nodes until a leaf's triangles are queued in [k, end) or the walk is over;
// returns this lane's number of visits (passes of the loop).
uint WalkToLeaf(vec3 origin, vec3 invDir, float tMax, inout uint i, inout uint k, inout uint end) {
  uint steps = 0u;
  bool walking = k >= end && i != kInvalidIndex;
  do {  // not while: see gLoopIterations
    if (walking) {
      ++steps;
      VisitNode(origin, invDir, tMax, i, k, end);
    }
    walking = k >= end && i != kInvalidIndex;
  } while (walking);
  return steps;
}

// Alpha (shared/alpha.h): a shader that defines VKPT_ALPHA (pathtrace.comp, as a
// specialization constant) has the scene access it needs; the trace-only kernel's
// triangles are all opaque.
#ifdef VKPT_ALPHA
#include "shared/alpha.h"
bool AlphaRejectsHit(Triangle t, vec3 r, uint alphaKey) {
  return VKPT_ALPHA && AlphaRejects(t.material, t.sourceIndex, r.y, r.z, alphaKey);
}
#else
bool AlphaRejectsHit(Triangle t, vec3 r, uint alphaKey) { return false; }
#endif

// The closest hit with t ∈ (0, tMax), or with anyHit the first hit found (a shadow ray
// needs no more), passing through the hits alpha leaves out (alphaKey: RayAlphaKey in
// shared/path.h). One function for both kinds, so that pathtrace.comp's lanes can trace
// whichever kind of ray each has next in the same loop.
HitRecord TraceRay(vec3 origin, vec3 dir, float tMax, bool anyHit, uint alphaKey) {
  HitRecord hit;
  hit.t = -1.0f;
  hit.b1 = 0.0f;
  hit.b2 = 0.0f;
  hit.triangle = kInvalidIndex;
  vec3 invDir = SafeInverse(dir);
  uint i = RootFor(dir);  // next node
  uint k = 0u;      // next triangle of the current leaf
  uint end = 0u;    // one past the current leaf's last triangle
  // Nodes are walked until a leaf (or the end), then its triangles are tested, in two
  // inner loops: on SIMD hardware one merged loop pays for both the box test and the
  // triangle test on every pass in which lanes disagree ("while-while" in Aila and Laine
  // 2009, "Understanding the Efficiency of Ray Traversal on GPUs").
  do {
    uint nodeSteps = WalkToLeaf(origin, invDir, tMax, i, k, end);
#ifdef VKPT_COUNT_BOX_TESTS
    gBoxTests += nodeSteps;
#endif
    uint triangleSteps = 0u;
    bool testing = k < end;
    do {
      if (testing) {
        ++triangleSteps;
        Triangle t = FetchTriangle(k);
        vec3 r = IntersectTriangle(t.v0, t.e1, t.e2, origin, dir, tMax);
        if (r.x >= 0.0f && !AlphaRejectsHit(t, r, alphaKey)) {
          tMax = r.x;
          hit.t = r.x;
          hit.b1 = r.y;
          hit.b2 = r.z;
          hit.triangle = k;
          if (anyHit) {  // ends both loops
            i = kInvalidIndex;
            end = k;
          }
        }
        ++k;
      }
      testing = k < end;
    } while (testing);
    CountNestedPass(nodeSteps, triangleSteps);
  } while (k < end || i != kInvalidIndex);  // every walk starts at a root: ≥ 1 pass each
  return hit;
}

HitRecord TraceClosest(vec3 origin, vec3 dir, float tMax, uint alphaKey) {
  return TraceRay(origin, dir, tMax, false, alphaKey);
}

// Any hit with t ∈ (0, tMax).
bool TraceOccluded(vec3 origin, vec3 dir, float tMax, uint alphaKey) {
  return TraceRay(origin, dir, tMax, true, alphaKey).t >= 0.0f;
}

#endif

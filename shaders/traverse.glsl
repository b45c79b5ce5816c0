// Stackless walk of a four-wide BVH for GLSL (shader::WideBvhNode, built by
// host/bvh/quantized_layout.cpp). The including shader enables
// GL_KHR_shader_subgroup_basic and GL_KHR_shader_subgroup_arithmetic; the scene comes
// from scene_fetch.glsl.
//
// A visit fetches one node (four texels) and tests its four children's quantised boxes
// (Ylitie et al. 2017, "Efficient Incoherent Ray Traversal on GPUs Through Compressed
// Wide BVHs"). The leaves hit are queued for the triangle loop; the walk descends to the
// nearest inner child hit and keeps the others on a short stack in registers (four
// entries, no per-invocation memory); when that overflows, the walk falls back on
// parent links, as the stackless multi-BVH traversal of Áfra and Szirmay-Kalos 2014
// ("Stackless Multi-BVH Traversal for CPU, MIC and GPU Ray Tracing") does throughout:
// back at a parent, it tests the children again and goes on after the one it came from.
// Each of the (up to) eight copies of the tree holds every node's children near first
// for one octant of ray directions, so "after" needs no sorting in the shader.
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
// copies (1, or 8 with each node's children near first for one octant of directions).
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
// VKPT_COUNT_BOX_TESTS: four per node visited.
#ifdef VKPT_COUNT_BOX_TESTS
uint gBoxTests = 0u;
#endif

// One pass of the outer do-while loop holding two inner ones, in which this lane ran
// its inner loops' bodies nodeSteps and triangleSteps times.
void CountNestedPass(uint nodeSteps, uint triangleSteps) {
  CountPasses(1u + max(subgroupMax(nodeSteps), 1u) + max(subgroupMax(triangleSteps), 1u));
}

uint Component(uvec4 v, uint k) { return k == 0u ? v.x : k == 1u ? v.y : k == 2u ? v.z : v.w; }

// Child k's planes along one axis (byte k of the word), as floats.
vec4 ChildPlanes(uint word) { return vec4((uvec4(word) >> uvec4(0u, 8u, 16u, 24u)) & 0xFFu); }

vec4 MinNotNaN4(vec4 a, vec4 b) { return mix(a, b, lessThan(b, a)); }
vec4 MaxNotNaN4(vec4 a, vec4 b) { return mix(a, b, lessThan(a, b)); }

// Bit k set: the ray enters child k's box before tMax. IntersectBox (shared/intersect.h)
// for the four children at once, on each plane origin + cell · q exactly as the host's
// ChildBox computes it (the box its tests check contains the subtree); the plane a ray
// enters by is the lower one where its direction is positive, which is what
// IntersectBox's minimum picks for a box with lo ≤ hi.
uint HitSlots(WideBvhNode node, vec3 origin, vec3 invDir, float tMax) {
  vec3 cell = uintBitsToFloat(((uvec3(node.exponents) >> uvec3(0u, 8u, 16u)) & 0xFFu) << 23u);
  bvec3 negative = lessThan(invDir, vec3(0.0f));
  uvec3 nearWords = mix(node.lo.xyz, node.hi.xyz, negative);
  uvec3 farWords = mix(node.hi.xyz, node.lo.xyz, negative);
  vec4 nearX = (node.origin.x + cell.x * ChildPlanes(nearWords.x) - origin.x) * invDir.x;
  vec4 nearY = (node.origin.y + cell.y * ChildPlanes(nearWords.y) - origin.y) * invDir.y;
  vec4 nearZ = (node.origin.z + cell.z * ChildPlanes(nearWords.z) - origin.z) * invDir.z;
  vec4 farX = (node.origin.x + cell.x * ChildPlanes(farWords.x) - origin.x) * invDir.x;
  vec4 farY = (node.origin.y + cell.y * ChildPlanes(farWords.y) - origin.y) * invDir.y;
  vec4 farZ = (node.origin.z + cell.z * ChildPlanes(farWords.z) - origin.z) * invDir.z;
  vec4 enter = MaxNotNaN4(MaxNotNaN4(nearX, nearY), MaxNotNaN4(nearZ, vec4(0.0f)));
  vec4 exit = MinNotNaN4(MinNotNaN4(farX, farY), MinNotNaN4(farZ, vec4(tMax))) * 1.0000004f;
  uvec4 hit = uvec4(lessThanEqual(enter, exit)) * uvec4(notEqual(node.child, uvec4(0u)));
  return hit.x | (hit.y << 1u) | (hit.z << 2u) | (hit.w << 3u);
}

// The walk's `fromSlot` when it arrives at a node from above, rather than back from the
// child in that slot.
const uint kFirstVisit = 4u;

// Inner children hit but not yet entered, nearest on top (x), in registers: four deep.
// A push onto a full stack drops the bottom entry and sets `dropped`; the walk then
// climbs by parent links once the stack runs out, testing each ancestor's children again
// and going on after the child it came from, which finds exactly the children dropped
// (children are entered in the ray's order, a subtree finished before its next sibling).
struct ShortStack {
  uvec4 entries;
  uint size;
  bool dropped;
};

ShortStack EmptyStack() {
  ShortStack s;
  s.entries = uvec4(0u);
  s.size = 0u;
  s.dropped = false;
  return s;
}

HitRecord NoHit() {
  HitRecord hit;
  hit.t = -1.0f;
  hit.b1 = 0.0f;
  hit.b2 = 0.0f;
  hit.triangle = kInvalidIndex;
  return hit;
}

void PushNode(inout ShortStack s, uint node) {
  s.dropped = s.dropped || s.size == 4u;
  s.size = min(s.size + 1u, 4u);
  s.entries = uvec4(node, s.entries.xyz);
}

// One step of the walk at node n, arriving from above or back from its child in
// `fromSlot`. Its children's boxes are tested; on the first visit the leaves hit are
// queued (leafSlots, with the node's child codes); then the walk descends to the nearest
// inner child hit (after fromSlot), pushing the others, or else pops the stack, or climbs
// to the parent if entries were dropped, or ends.
void VisitNode(vec3 origin, vec3 invDir, float tMax, inout uint n, inout uint fromSlot, inout ShortStack stack,
               inout uvec4 leafCodes, inout uint leafSlots) {
  WideBvhNode node = FetchWideNode(n);
  uint hits = HitSlots(node, origin, invDir, tMax);
  uvec4 isLeaf = uvec4(notEqual(node.child & 15u, uvec4(0u)));
  uint leaves = isLeaf.x | (isLeaf.y << 1u) | (isLeaf.z << 2u) | (isLeaf.w << 3u);
  uint inner = hits & ~leaves;
  if (fromSlot == kFirstVisit) {
    leafSlots = hits & leaves;
    leafCodes = node.child;
  } else {
    inner &= ~((2u << fromSlot) - 1u);
  }
  if (inner != 0u) {
    uint nearest = uint(findLSB(inner));
    if ((inner & 8u) != 0u && nearest < 3u) PushNode(stack, node.child.w >> 4u);
    if ((inner & 4u) != 0u && nearest < 2u) PushNode(stack, node.child.z >> 4u);
    if ((inner & 2u) != 0u && nearest < 1u) PushNode(stack, node.child.y >> 4u);
    n = Component(node.child, nearest) >> 4u;
    fromSlot = kFirstVisit;
  } else if (stack.size > 0u) {
    n = stack.entries.x;
    stack.entries = uvec4(stack.entries.yzw, 0u);
    --stack.size;
    fromSlot = kFirstVisit;
  } else if (stack.dropped) {
    fromSlot = (node.exponents >> 24u) & 3u;
    n = node.lo.w;
  } else {
    n = kInvalidIndex;
  }
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
  HitRecord hit = NoHit();
  vec3 invDir = SafeInverse(dir);
  uint n = RootFor(dir);  // the node to visit next
  uint fromSlot = kFirstVisit;
  ShortStack stack = EmptyStack();
  uvec4 leafCodes = uvec4(0u);  // the child codes of the node whose leaves are queued
  uint leafSlots = 0u;          // the slots of its leaves still to test
  uint k = 0u;      // next triangle of the current leaf
  uint end = 0u;    // one past the current leaf's last triangle
  // Nodes are walked until some leaves are queued (or the end), then their triangles are
  // tested, in two inner loops: on SIMD hardware one merged loop pays for both the box
  // tests and the triangle test on every pass in which lanes disagree ("while-while" in
  // Aila and Laine 2009, "Understanding the Efficiency of Ray Traversal on GPUs").
  do {
    uint nodeSteps = 0u;
    bool walking = n != kInvalidIndex;
    do {  // not while: see gLoopIterations
      if (walking) {
        ++nodeSteps;
        VisitNode(origin, invDir, tMax, n, fromSlot, stack, leafCodes, leafSlots);
      }
      walking = leafSlots == 0u && n != kInvalidIndex;
    } while (walking);
#ifdef VKPT_COUNT_BOX_TESTS
    gBoxTests += 4u * nodeSteps;
#endif
    uint triangleSteps = 0u;
    bool testing = leafSlots != 0u;
    do {
      if (testing) {
        if (k >= end) {
          uint code = Component(leafCodes, uint(findLSB(leafSlots)));
          leafSlots &= leafSlots - 1u;
          k = code >> 4u;
          end = k + (code & 15u);
        }
        ++triangleSteps;
        Triangle t = FetchTriangle(k);
        vec3 r = IntersectTriangle(t.v0, t.e1, t.e2, origin, dir, tMax);
        if (r.x >= 0.0f && !AlphaRejectsHit(t, r, alphaKey)) {
          tMax = r.x;
          hit.t = r.x;
          hit.b1 = r.y;
          hit.b2 = r.z;
          hit.triangle = k;
          if (anyHit) {  // ends all three loops
            n = kInvalidIndex;
            leafSlots = 0u;
            end = k;
          }
        }
        ++k;
      }
      testing = k < end || leafSlots != 0u;
    } while (testing);
    CountNestedPass(nodeSteps, triangleSteps);
  } while (n != kInvalidIndex);  // every walk starts at the root: ≥ 1 pass each
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

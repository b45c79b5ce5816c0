#version 460
// Trace-only kernel: the closest hit of each ray in a buffer, with the same stackless
// traversal as pathtrace.comp. Used by tests (GPU vs CPU brute force) and benchmarks.
// One ray per invocation: far below lavapipe's 65535-iteration limit for any sane BVH.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require

#include "shared/layout.h"

layout(local_size_x = 64) in;

layout(std430, binding = kBindingRays) readonly buffer Rays { RayQuery rays[]; };
layout(std430, binding = kBindingHits) writeonly buffer Hits { HitRecord hits[]; };
// nodeCount and nodeCopies as in FrameParams; the triangles from triangleSplit on are in a
// second texel buffer when kTwoTriangleBuffers is 1 (scene_fetch.glsl).
layout(push_constant) uniform Push { uint nodeCount; uint nodeCopies; uint triangleSplit; };
layout(constant_id = 0) const uint kTwoTriangleBuffers = 0u;
#define VKPT_TWO_TRIANGLE_BUFFERS (kTwoTriangleBuffers != 0u)

#include "traverse.glsl"

void main() {
  gNodeCount = nodeCount;
  gNodeCopies = nodeCopies;
  gTriangleSplit = triangleSplit;
  uint i = gl_GlobalInvocationID.x;
  // No early return: every lane takes part in the subgroup operations of the traversal.
  bool inside = i < uint(rays.length());
  RayQuery r = rays[inside ? i : 0u];
  HitRecord h = TraceClosest(r.origin, r.dir, r.tMax, 0u);
  if (inside) hits[i] = h;
}

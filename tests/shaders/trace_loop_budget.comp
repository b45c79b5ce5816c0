#version 460
// Test kernel (tests/test_gpu.cpp): shaders/trace.comp's closest-hit trace, which then
// checks the traversal's count of loop passes (traverse.glsl's gLoopIterations) against
// lavapipe's limit itself. Both traversals run; then a probe loop of L passes is sized
// so that, if the count C is exact, it ends on the last pass the limit allows (pad0 = 0:
// the probe completes, j = L) or one pass past it (pad0 = 1: j = L - 1). Same bindings,
// push constants and specialization constant as trace.comp, so GpuRenderer::Trace runs it.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require

#include "shared/layout.h"

layout(local_size_x = 64) in;

layout(std430, binding = kBindingRays) readonly buffer Rays { RayQuery rays[]; };
layout(std430, binding = kBindingHits) writeonly buffer Hits { HitRecord hits[]; };
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
  TraceOccluded(r.origin, r.dir, h.t > 0.0f ? h.t : r.tMax, 0u);
  uint counted = subgroupAdd(gLoopIterations);
  uint probe = 65535u + r.pad0 - counted;
  uint j = 0u;
  while (j < probe) ++j;
  h.t = uintBitsToFloat(j);
  h.b1 = uintBitsToFloat(probe);
  h.b2 = uintBitsToFloat(counted);
  if (inside) hits[i] = h;
}

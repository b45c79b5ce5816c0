#version 460
// vkpt's path tracer on a Vulkan compute device: one invocation per pixel and sample,
// the estimator of shared/path.h (the very code the CPU reference runs), and a stackless
// BVH walk. One sample per invocation keeps each invocation's loop count small (see
// traverse.glsl on lavapipe's loop limit); a submission holds several dispatches.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require

#include "shared/layout.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = kBindingParams) uniform Params { FrameParams params; };
// Per pixel: [2i] = (Σ L, unused), [2i + 1] = (Σ L², unused), over all samples so far.
layout(std430, binding = kBindingAccum) buffer Accum { vec4 accum[]; };
// Per pixel: (rays traced, non-finite samples discarded, samples possibly cut short, 0).
layout(std430, binding = kBindingCounters) buffer Counters { uvec4 counters[]; };
// Which sample of the batch this dispatch computes: params.sampleBegin + sampleInBatch.
layout(push_constant) uniform Push { uint sampleInBatch; };

#define VKPT_SCENE_PARAM
#define VKPT_SCENE_ARG
#define VKPT_TRIANGLE(i) FetchTriangle(i)
#define VKPT_MATERIAL(i) FetchMaterial(i)
#define VKPT_EMITTER(i) FetchEmitter(i)

#include "traverse.glsl"

#include "shared/path.h"

// lavapipe ends a shader once its SIMD group has run 65535 loop iterations in total;
// stay clear of it by a margin for the small loops not counted exactly.
const uint kLoopBudget = 65535u - 256u;

void main() {
  gNodeCount = params.nodeCount;
  gNodeCopies = params.nodeCopies;
  uvec2 pixel = gl_GlobalInvocationID.xy;
  bool inside = pixel.x < params.width && pixel.y < params.height;
  PathSample ps;
  ps.radiance = vec3(0.0f);
  ps.rays = 0u;
  // Out-of-image lanes still take part in the subgroup operations below (no early return).
  if (inside) ps = TracePath(params, pixel.x, pixel.y, params.sampleBegin + sampleInBatch);
  // Loops outside traversal: the path loop (≤ one iteration per ray) and the emitter
  // binary search (≤ log2(emitters) + 2 per ray), bounded per lane and summed.
  uint smallLoops = ps.rays * (3u + uint(findMSB(max(params.emitterCount, 1u))));
  uint groupIterations = subgroupAdd(gLoopIterations) + subgroupAdd(smallLoops);
  if (!inside) return;
  uint index = pixel.y * params.width + pixel.x;
  vec3 L = ps.radiance;
  uvec4 count = uvec4(ps.rays, 0u, groupIterations >= kLoopBudget ? 1u : 0u, 0u);
  if (any(isnan(L)) || any(isinf(L))) {
    count.y = 1u;
  } else {
    accum[2u * index] += vec4(L, 0.0f);
    accum[2u * index + 1u] += vec4(L * L, 0.0f);
  }
  counters[index] += count;
}

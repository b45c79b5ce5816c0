#version 460
// vkpt's AOVs on a Vulkan compute device: one invocation per pixel adds the AOV samples
// of shared/aov.h (the code the CPU runs) to its pixel's sums, one sample per dispatch,
// with the stackless walk of traverse.glsl counting the camera ray's box tests. An AOV
// sample traces at most 1 + kAovSpecularBounces rays, far inside lavapipe's loop budget.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require

#include "shared/layout.h"

layout(local_size_x = 8, local_size_y = 8) in;

// A storage buffer, as in pathtrace.comp (which says why).
layout(std430, binding = kBindingParams) readonly buffer Params { FrameParams params; };
// Per pixel, kAovSumsPerPixel vec4 (layout.h): (Σ albedo, Σ depth), (Σ normal, hits),
// (Σ position, Σ box tests).
layout(std430, binding = kBindingAovSums) buffer AovSums { vec4 aovSums[]; };
// Per pixel, the scene triangle the id AOVs name (PixelCentreTriangle): written with
// `ids` by the dispatch of sample 0; without, the buffer is a stand-in of one uint.
layout(std430, binding = kBindingAovTriangles) buffer AovTriangles { uint aovTriangles[]; };
// This dispatch adds AOV sample `sampleIndex`.
layout(push_constant) uniform Push {
  uint sampleIndex;
  uint ids;
};

#include "scene_constants.glsl"
#define VKPT_COUNT_BOX_TESTS
#include "traverse.glsl"
#include "shared/estimator.h"

HitRecord TraceCounted(vec3 origin, vec3 dir, uint alphaKey, inout uint boxTests) {
  uint before = gBoxTests;
  HitRecord hit = TraceRay(origin, dir, kInfinity, false, alphaKey);
  boxTests += gBoxTests - before;
  return hit;
}

#include "shared/aov.h"

bool IsFinite(vec3 v) { return !any(isnan(v)) && !any(isinf(v)); }

void main() {
  gNodeCount = params.nodeCount;
  gNodeCopies = params.nodeCopies;
  gTexelSplit = params.texelSplit;
  gTriangleSplit = params.triangleSplit;
  gLightNodeBase = kTexelsPerLight * params.lightCount;
  gUvSplit = params.uvSplit;
  uvec2 pixel = gl_GlobalInvocationID.xy;
  // Every lane runs the walk (subgroup operations count its loop passes); only those in
  // the image add what they found.
  bool inside = pixel.x < params.width && pixel.y < params.height;
  uvec2 traced = min(pixel, uvec2(params.width, params.height) - 1u);
  if (ids != 0u && sampleIndex == 0u) {
    uint triangle = PixelCentreTriangle(params, traced.x, traced.y);
    if (inside) aovTriangles[pixel.y * params.width + pixel.x] = triangle;
  }
  AovSample a = TraceAovSample(params, traced.x, traced.y, sampleIndex);
  if (!inside || !IsFinite(a.albedo) || !IsFinite(a.normal) || !IsFinite(a.position) || isnan(a.depth) ||
      isinf(a.depth))
    return;
  uint i = kAovSumsPerPixel * (pixel.y * params.width + pixel.x);
  aovSums[i] += vec4(a.albedo, a.depth);
  aovSums[i + 1u] += vec4(a.normal, float(a.hit));
  aovSums[i + 2u] += vec4(a.position, float(a.boxTests));
}

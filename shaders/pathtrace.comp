#version 460
// vkpt's path tracer on a Vulkan compute device: one invocation per pixel, the estimator
// of shared/path.h (the very code the CPU reference runs), and a stackless BVH walk.
#extension GL_GOOGLE_include_directive : require

#include "shared/layout.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = kBindingParams) uniform Params { FrameParams params; };
layout(std430, binding = kBindingTriangles) readonly buffer Triangles { Triangle triangles[]; };
layout(std430, binding = kBindingNodes) readonly buffer Nodes { BvhNode nodes[]; };
layout(std430, binding = kBindingMaterials) readonly buffer Materials { Material materials[]; };
layout(std430, binding = kBindingEmitters) readonly buffer Emitters { Emitter emitters[]; };
// Per pixel: [2i] = (Σ L, unused), [2i + 1] = (Σ L², unused), over all samples so far.
layout(std430, binding = kBindingAccum) buffer Accum { vec4 accum[]; };
// Per pixel: (rays traced, non-finite samples discarded).
layout(std430, binding = kBindingCounters) buffer Counters { uvec2 counters[]; };

#define VKPT_SCENE_PARAM
#define VKPT_SCENE_ARG
#define VKPT_TRIANGLE(i) triangles[i]
#define VKPT_MATERIAL(i) materials[i]
#define VKPT_EMITTER(i) emitters[i]

#include "shared/estimator.h"
#include "shared/intersect.h"

// Stackless traversal over the depth-first skip-link layout (Smits 1998, "Efficiency
// Issues for Ray Tracing"): a node whose box is hit (within the closest hit so far) is
// entered by going to the next node; a missed box or a finished leaf jumps to its skip
// link. No stack means no per-invocation memory and no divergence in stack depth.
HitRecord TraceClosest(vec3 origin, vec3 dir, float tMax) {
  HitRecord hit;
  hit.t = -1.0f;
  hit.b1 = 0.0f;
  hit.b2 = 0.0f;
  hit.triangle = kInvalidIndex;
  vec3 invDir = SafeInverse(dir);
  uint i = 0u;
  while (i != kInvalidIndex) {
    BvhNode node = nodes[i];
    if (IntersectBox(node.lo, node.hi, origin, invDir, tMax) < 0.0f) {
      i = node.skip;
      continue;
    }
    if (node.leaf == 0u) {
      i = i + 1u;
      continue;
    }
    uint first = node.leaf >> 4u;
    uint end = first + (node.leaf & 15u);
    for (uint k = first; k < end; ++k) {
      Triangle t = triangles[k];
      vec3 r = IntersectTriangle(t.v0, t.e1, t.e2, origin, dir, tMax);
      if (r.x >= 0.0f) {
        tMax = r.x;
        hit.t = r.x;
        hit.b1 = r.y;
        hit.b2 = r.z;
        hit.triangle = k;
      }
    }
    i = node.skip;
  }
  return hit;
}

bool TraceOccluded(vec3 origin, vec3 dir, float tMax) {
  vec3 invDir = SafeInverse(dir);
  uint i = 0u;
  while (i != kInvalidIndex) {
    BvhNode node = nodes[i];
    if (IntersectBox(node.lo, node.hi, origin, invDir, tMax) < 0.0f) {
      i = node.skip;
      continue;
    }
    if (node.leaf == 0u) {
      i = i + 1u;
      continue;
    }
    uint first = node.leaf >> 4u;
    uint end = first + (node.leaf & 15u);
    for (uint k = first; k < end; ++k) {
      Triangle t = triangles[k];
      if (IntersectTriangle(t.v0, t.e1, t.e2, origin, dir, tMax).x >= 0.0f) return true;
    }
    i = node.skip;
  }
  return false;
}

#include "shared/path.h"

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  if (pixel.x >= params.width || pixel.y >= params.height) return;
  uint index = pixel.y * params.width + pixel.x;
  vec3 sum = vec3(0.0f);
  vec3 sumSq = vec3(0.0f);
  uint rays = 0u;
  uint nonFinite = 0u;
  for (uint s = 0u; s < params.sampleCount; ++s) {
    PathSample ps = TracePath(params, pixel.x, pixel.y, params.sampleBegin + s);
    rays += ps.rays;
    vec3 L = ps.radiance;
    if (any(isnan(L)) || any(isinf(L))) {
      nonFinite += 1u;
      continue;
    }
    sum += L;
    sumSq += L * L;
  }
  accum[2u * index] += vec4(sum, 0.0f);
  accum[2u * index + 1u] += vec4(sumSq, 0.0f);
  counters[index] += uvec2(rays, nonFinite);
}

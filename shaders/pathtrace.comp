#version 460
// vkpt's path tracer on a Vulkan compute device: one invocation per pixel, computing a
// run of that pixel's samples with the estimator of shared/path.h (the very code the CPU
// reference runs) and a stackless BVH walk.
//
// Path regeneration (Novák et al. 2010): the invocation traces one ray of its path per
// loop pass (a bounce or a shadow ray), and a lane whose path has ended starts its next
// sample at once. On SIMD hardware (lavapipe runs 8 invocations as the lanes of one
// vector) a loop makes as many passes as its slowest lane; with one path per invocation
// the lanes of short paths idled while the longest one went on, with a run of samples
// the lengths even out.
//
// lavapipe ends a shader after 65535 loop passes per SIMD group (traverse.glsl), so the
// run must stay short enough: the host sizes it from the passes per sample measured in
// the previous submission (kBindingLoopStats), and every sample of a group that may have
// been cut short is counted as such.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require

#include "shared/layout.h"

layout(local_size_x = 8, local_size_y = 8) in;

// The frame's constants are a storage buffer, not a uniform buffer: lavapipe (Mesa 22.3)
// inlines uniform-buffer values that decide a branch or a loop (main() below copies some
// into globals, which makes it insist), re-optimising and recompiling the whole shader at
// every bind of the pipeline and keeping each copy until the pipeline is destroyed: 850 KB
// a queue submission, a render's memory growing with its length (docs/design-notes.md,
// "Frame constants in a storage buffer"). No value is inlined from a storage buffer.
layout(std430, binding = kBindingParams) readonly buffer Params { FrameParams params; };
// Per pixel: [2i] = (Σ L, unused), [2i + 1] = (Σ L², unused), over all samples so far.
layout(std430, binding = kBindingAccum) buffer Accum { vec4 accum[]; };
// Per pixel: (rays traced, non-finite samples discarded, samples possibly cut short,
// samples taken).
layout(std430, binding = kBindingCounters) buffer Counters { uvec4 counters[]; };
// Adaptive sampling (params.adaptive == 1): the pixels that take this dispatch's samples.
layout(std430, binding = kBindingActive) readonly buffer Active { uint activePixels[]; };
// The most loop passes any SIMD group has needed per sample (rounded up), for the host's
// choice of samplesPerInvocation.
layout(std430, binding = kBindingLoopStats) buffer LoopStats { uint maxPassesPerSample; };
// This dispatch computes samples params.sampleBegin + firstSample + [0, samples).
layout(push_constant) uniform Push {
  uint firstSample;
  uint samples;
};

#include "scene_constants.glsl"
#include "traverse.glsl"

#include "shared/path.h"

// The frame's constants the scene's fetches read (scene_constants.glsl), copied to globals.
void SetSceneConstants() {
  gNodeCount = params.nodeCount;
  gNodeCopies = params.nodeCopies;
  gTexelSplit = params.texelSplit;
  gTriangleSplit = params.triangleSplit;
  gLightNodeBase = kTexelsPerLight * params.lightCount;
  gUvSplit = params.uvSplit;
}

// This invocation's pixel. lavapipe hands each thread one contiguous range of workgroups
// (the top and bottom half of the image with two threads), so costly regions would leave
// a thread idle: rows of tiles are dealt out with a stride coprime to their count (host:
// TileRowStride).
uvec2 DealtPixel() {
  uint tileRows = (params.height + 7u) / 8u;
  uint tileRow = gl_WorkGroupID.y * params.tileRowStride % tileRows;
  return uvec2(gl_GlobalInvocationID.x, tileRow * 8u + gl_LocalInvocationID.y);
}

// A finished sample's radiance added to the pixel's sums, or counted as non-finite.
void AddSample(vec3 L, inout vec4 sum, inout vec4 sumSq, inout uvec4 count) {
  if (any(isnan(L)) || any(isinf(L))) {
    count.y += 1u;
  } else {
    sum += vec4(L, 0.0f);
    sumSq += vec4(L * L, 0.0f);
  }
}

// The loop passes of this invocation's subgroup, all loops counted: traversal's
// (gLoopIterations), this kernel's (≤ one pass per ray), the light binary search
// (≤ log2(lights) + 2 per ray) and the light tree's two descents (a light sample's and an
// emitter's pmf: ≤ its depth + 1 passes each per ray), bounded per lane and summed. The
// most per sample goes to maxPassesPerSample.
uint GroupLoopPasses(uint rays) {
  uint treePasses = params.treeLights > 0u ? 2u * (params.treeDepth + 1u) : 0u;
  uint smallLoops = rays * (3u + uint(findMSB(max(params.lightCount, 1u))) + treePasses);
  uint groupPasses = subgroupAdd(gLoopIterations) + subgroupAdd(smallLoops);
  if (subgroupElect()) atomicMax(maxPassesPerSample, (groupPasses + samples - 1u) / samples);
  return groupPasses;
}

void main() {
  SetSceneConstants();
  uvec2 pixel = DealtPixel();
  uint index = pixel.y * params.width + pixel.x;
  bool inside = pixel.x < params.width && pixel.y < params.height;
  if (inside && params.adaptive != 0u) inside = activePixels[index] != 0u;
  // The sums are carried in registers and added to in sample order, as if each sample
  // were its own dispatch: the image does not depend on how samples are grouped.
  vec4 sum = vec4(0.0f);
  vec4 sumSq = vec4(0.0f);
  uvec4 count = uvec4(0u);
  if (inside) {
    sum = accum[2u * index];
    sumSq = accum[2u * index + 1u];
    count = counters[index];
  }
  uint first = params.sampleBegin + firstSample;
  uint done = 0u;
  uint rays = 0u;
  PathState path = StartPath(params, pixel.x, pixel.y, first);
  bool more = true;  // the path has a closest-hit ray to trace
  // Out-of-image and inactive lanes still take part in the subgroup operations (no
  // early return).
  bool tracing = inside;
  while (tracing) {
    // One ray per pass, of either kind: lanes tracing shadow rays and lanes tracing
    // bounce rays share the traversal loops instead of waiting for each other.
    bool shadow = path.shadowPending;
    Ray ray = shadow ? path.shadowRay : path.ray;
    HitRecord hit = TraceRay(ray.origin, ray.dir, shadow ? path.shadowTMax : kInfinity, shadow,
                             RayAlphaKey(params, path, shadow));
    if (shadow) AddLightIfVisible(path, hit.t >= 0.0f);
    else more = ShadeHit(params, path, hit);
    if (!more && !path.shadowPending) {
      rays += path.result.rays;
      AddSample(path.result.radiance, sum, sumSq, count);
      ++done;
      if (done == samples) {
        tracing = false;
      } else {
        path = StartPath(params, pixel.x, pixel.y, first + done);
        more = true;
      }
    }
  }
  uint groupPasses = GroupLoopPasses(rays);
  if (!inside) return;
  count.x += rays;
  count.w += samples;
  if (groupPasses >= kLoopBudget) count.z += samples;
  accum[2u * index] = sum;
  accum[2u * index + 1u] = sumSq;
  counters[index] = count;
}

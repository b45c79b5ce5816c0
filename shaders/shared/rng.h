// Counter-based random numbers shared bit-for-bit by the CPU and GPU renderers.
//
// There is no RNG state: the d-th random number of sample s of pixel p under seed k
// is a pure function of (k, p, s, d). This makes every pixel independent of thread
// count, tile order and dispatch batching, and lets the CPU and GPU run the very same
// random streams (lockstep comparison). The hash is pcg4d (Jarzynski & Olano 2020,
// "Hash Functions for GPU Rendering", JCGT 9(3)): a bijection of 128-bit inputs, so two
// different (seed, pixel, sample, group) keys can never share their random numbers.
// Each call yields four numbers, dimensions 4*group .. 4*group + 3.
#ifndef VKPT_RNG_H
#define VKPT_RNG_H
#include "prelude.h"

VKPT_BEGIN_NAMESPACE

VKPT_FN uvec4 Pcg4d(uvec4 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  v = v ^ (v >> 16u);
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  return v;
}

// The top 24 bits as a float in [0, 1): exact in binary32 on both sides, never 1.0.
VKPT_FN float ToUnitFloat(uint bits) { return float(bits >> 8u) * (1.0f / 16777216.0f); }

VKPT_FN vec4 Random4(uint seed, uint pixel, uint sampleIndex, uint group) {
  uvec4 h = Pcg4d(uvec4(pixel, sampleIndex, group, seed));
  return vec4(ToUnitFloat(h.x), ToUnitFloat(h.y), ToUnitFloat(h.z), ToUnitFloat(h.w));
}

// How the estimator spends its dimensions (groups of four), identically on CPU and GPU.
const uint kGroupCamera = 0u;  // x: film jitter x, y: film jitter y
// At path vertex `bounce` (0 = the camera hit):
//   LightGroup: x: emitter choice, y, z: point on the emitter, w: Russian roulette
//   BsdfGroup:  x, y: scattered direction
VKPT_FN uint LightGroup(uint bounce) { return 1u + 2u * bounce; }
VKPT_FN uint BsdfGroup(uint bounce) { return 2u + 2u * bounce; }

VKPT_END_NAMESPACE

#endif

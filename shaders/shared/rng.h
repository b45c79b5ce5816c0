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

VKPT_FN uvec4 RandomBits4(uint seed, uint pixel, uint sampleIndex, uint group) {
  return Pcg4d(uvec4(pixel, sampleIndex, group, seed));
}

VKPT_FN vec4 Random4(uint seed, uint pixel, uint sampleIndex, uint group) {
  uvec4 h = RandomBits4(seed, pixel, sampleIndex, group);
  return vec4(ToUnitFloat(h.x), ToUnitFloat(h.y), ToUnitFloat(h.z), ToUnitFloat(h.w));
}

// --- Low-discrepancy 2-D samples -----------------------------------------------------
// Shuffled, Owen-scrambled Sobol points (Burley 2020, "Practical Hash-based Owen
// Scrambling", JCGT 9(4)): within one pixel, the first 2^k samples of a dimension pair are
// stratified in every elementary interval of the unit square (a (0,2)-sequence), so
// camera jitter, light points and bounce directions converge faster than with independent
// random numbers. Each pair gets its own scramble and its own shuffle of the sample
// order, which keeps pairs (and pixels) statistically independent. Integer-only and
// loop-free, so it is bit-identical on CPU and GPU and costs lavapipe no loop iterations.

VKPT_FN uint ReverseBits(uint x) {
  x = ((x >> 1u) & 0x55555555u) | ((x & 0x55555555u) << 1u);
  x = ((x >> 2u) & 0x33333333u) | ((x & 0x33333333u) << 2u);
  x = ((x >> 4u) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4u);
  x = ((x >> 8u) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8u);
  return (x >> 16u) | (x << 16u);
}

// Laine–Karras style hash that only lets bits influence *higher* bits: on bit-reversed
// values that is a random nested uniform (Owen) scramble.
VKPT_FN uint LaineKarrasPermutation(uint x, uint seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

VKPT_FN uint NestedUniformScramble(uint x, uint seed) {
  return ReverseBits(LaineKarrasPermutation(ReverseBits(x), seed));
}

// Second Sobol dimension without a loop. Its generator matrix is Pascal's triangle mod 2:
// output digit m collects index bits b with C(b, m) odd, i.e. (Lucas) m ⊆ b. That is a
// superset transform over the 5-bit positions, done in five masked xor-shifts. This
// returns the digits in index bit order (digit m at bit m); SobolSecondDimension reverses
// them into a binary fraction.
VKPT_FN uint SobolSecondDigits(uint index) {
  uint y = index;
  y ^= (y >> 1u) & 0x55555555u;
  y ^= (y >> 2u) & 0x33333333u;
  y ^= (y >> 4u) & 0x0F0F0F0Fu;
  y ^= (y >> 8u) & 0x00FF00FFu;
  y ^= (y >> 16u) & 0x0000FFFFu;
  return y;
}

VKPT_FN uint SobolSecondDimension(uint index) { return ReverseBits(SobolSecondDigits(index)); }

// Point `sampleIndex` of dimension pair `pair` of `pixel`, in [0,1)²: the shuffled index
// (an Owen-scrambled sample index), then Owen-scrambled Sobol dimensions 1 and 2 of it.
// Written out, NestedUniformScramble(ReverseBits(v), s) is ReverseBits(Lk(v, s)) — the
// first dimension is the bit-reversed index, and SobolSecondDimension ends in a
// reversal — so the paired reversals are left out; the values are those of the
// composition exactly.
VKPT_FN vec2 Sample2D(uint seed, uint pixel, uint sampleIndex, uint pair) {
  uvec4 h = Pcg4d(uvec4(pixel, pair, seed, 0x50B0150Bu));
  uint index = NestedUniformScramble(sampleIndex, h.x);
  uint x = ReverseBits(LaineKarrasPermutation(index, h.y));
  uint y = ReverseBits(LaineKarrasPermutation(SobolSecondDigits(index), h.z));
  return vec2(ToUnitFloat(x), ToUnitFloat(y));
}

// How the estimator spends its dimensions (groups of four), identically on CPU and GPU.
// Pair kGroupCamera of Sample2D: film jitter. At path vertex `bounce` (0 = camera hit):
//   Random4(LightGroup): x: the BSDF lobe, w: Russian roulette
//   RandomBits4(LightGroup): y: the alpha key (alpha.h) of the ray that finds the vertex
//                        (the camera ray for vertex 0), z: that of the vertex's shadow ray
//   Sample2D(LightGroup): the light and the point on it
//   Sample2D(BsdfGroup):  the scattered direction within the lobe
// Pair kGroupWavelength of Sample2D, x: the hero wavelength, drawn once per path
// (dispersion.h), at no fixed vertex; beyond the pairs of any reachable bounce.
const uint kGroupCamera = 0u;
const uint kGroupWavelength = 0xFFFFFFFFu;
VKPT_FN uint LightGroup(uint bounce) { return 1u + 2u * bounce; }
VKPT_FN uint BsdfGroup(uint bounce) { return 2u + 2u * bounce; }

VKPT_END_NAMESPACE

#endif

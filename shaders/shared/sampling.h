// Sampling routines and their densities, shared by the CPU and GPU renderers.
#ifndef VKPT_SAMPLING_H
#define VKPT_SAMPLING_H
#include "prelude.h"

VKPT_BEGIN_NAMESPACE

const float kPi = 3.14159265358979323846f;
const float kInvPi = 0.31830988618379067154f;
// The largest float below 1 (1 − 2⁻²⁴): keeps remapped uniforms inside [0, 1).
const float kOneMinusEpsilon = 0.99999994f;

// Orthonormal basis around unit vector n (Duff et al. 2017, "Building an Orthonormal
// Basis, Revisited", JCGT 6(1)): branch-free and without the singularity at n.z = -1.
struct Frame {
  vec3 t;
  vec3 b;
  vec3 n;
};

VKPT_FN Frame FrameFromNormal(vec3 n) {
  float s = n.z >= 0.0f ? 1.0f : -1.0f;
  float a = -1.0f / (s + n.z);
  float c = n.x * n.y * a;
  Frame f;
  f.t = vec3(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
  f.b = vec3(c, s + n.y * n.y * a, -n.y);
  f.n = n;
  return f;
}

VKPT_FN vec3 FrameToWorld(Frame f, vec3 v) { return f.t * v.x + f.b * v.y + f.n * v.z; }
VKPT_FN vec3 WorldToFrame(Frame f, vec3 v) { return vec3(dot(v, f.t), dot(v, f.b), dot(v, f.n)); }

// atan2(y, x) from +, ×, ÷ and a polynomial (Abramowitz & Stegun 4.4.49 on [0, 1], error
// ≤ 2e-8 rad), so that CPU and GPU agree to the last few bits: lavapipe's atan and acos
// differ from the C library's by ~1e-4 relative, which moves an environment lookup by a
// tenth of a texel. Returns 0 for (0, 0).
VKPT_FN float PortableAtan2(float y, float x) {
  float ax = abs(x);
  float ay = abs(y);
  float hi = max(ax, ay);
  float t = hi > 0.0f ? min(ax, ay) / hi : 0.0f;
  float t2 = t * t;
  float p = -0.0040540580f;
  p = p * t2 + 0.0218612288f;
  p = p * t2 - 0.0559098861f;
  p = p * t2 + 0.0964200441f;
  p = p * t2 - 0.1390853351f;
  p = p * t2 + 0.1994653599f;
  p = p * t2 - 0.3332985605f;
  p = p * t2 + 0.9999993329f;
  float r = p * t;
  if (ay > ax) r = 0.5f * kPi - r;
  if (x < 0.0f) r = kPi - r;
  return y < 0.0f ? -r : r;
}

// acos(c) for c ∈ [−1, 1], by PortableAtan2.
VKPT_FN float PortableAcos(float c) { return PortableAtan2(sqrt(max(0.0f, 1.0f - c * c)), c); }

// Veach's power heuristic (β = 2) for the sample of density pdfA against pdfB, written
// as 1 / (1 + (pdfB/pdfA)²) so that large densities (a small, distant light) cannot
// overflow a square.
VKPT_FN float PowerHeuristic(float pdfA, float pdfB) {
  float r = pdfB / pdfA;
  return pdfA > 0.0f ? 1.0f / (1.0f + r * r) : 0.0f;
}

// Cosine-weighted direction on the hemisphere around +z (Malley's method: uniform on
// the unit disk, projected up). pdf(ω) = cos θ / π, so for a Lambertian BRDF ρ/π the
// Monte Carlo weight f cos θ / pdf is exactly ρ.
VKPT_FN vec3 SampleCosineHemisphere(float u1, float u2) {
  float r = sqrt(u1);
  float phi = 2.0f * kPi * u2;
  return vec3(r * cos(phi), r * sin(phi), sqrt(max(0.0f, 1.0f - u1)));
}

VKPT_FN float CosineHemispherePdf(float cosTheta) { return max(cosTheta, 0.0f) * kInvPi; }

// Uniform point on a triangle as barycentrics (b1, b2) of v1 and v2 (pbrt-v3 §13.6.5:
// the square-root warp). The area density is 1 / area.
VKPT_FN vec2 SampleUniformTriangle(float u1, float u2) {
  float su = sqrt(u1);
  return vec2(u2 * su, 1.0f - su);
}

// Radiance-to-weight helper: the relative luminance used to build the light CDF and
// (as its maximum component) Russian roulette.
VKPT_FN float MaxComponent(vec3 v) { return max(v.x, max(v.y, v.z)); }
VKPT_FN float Luminance(vec3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

// Defines VKPT_FN uint NAME(VKPT_SCENE_PARAM uint first, uint count, float u): the
// interval of the inclusive CDF FETCH(first), …, FETCH(first + count − 1) (the last 1)
// that holds u ∈ [0, 1), the smallest k with u < FETCH(first + k), so that an interval
// of zero width is never chosen. One binary search for every table (the lights', the
// environment map's rows and columns), each read through its own fetch macro, as GLSL
// has neither templates nor function pointers.
#define VKPT_DEFINE_CDF_SEARCH(NAME, FETCH)                             \
  VKPT_FN uint NAME(VKPT_SCENE_PARAM uint first, uint count, float u) { \
    uint lo = 0u;                                                       \
    uint hi = count - 1u;                                               \
    while (lo < hi) {                                                   \
      uint mid = (lo + hi) / 2u;                                        \
      if (u < FETCH(first + mid)) hi = mid;                             \
      else lo = mid + 1u;                                               \
    }                                                                   \
    return lo;                                                          \
  }

VKPT_END_NAMESPACE

#endif

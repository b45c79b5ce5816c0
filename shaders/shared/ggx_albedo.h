// Directional albedo of the GGX lobe (microfacet.h), for energy compensation in bsdf.h.
//
// kAlbedoTables (albedo_tables.h; scripts/make_ggx_albedo_table.cpp writes its numbers)
// holds, on a kGgxAlbedoSize² grid over sqrt(cos θ) ∈ [0,1] (rows: E changes fastest at
// grazing angles) and roughness = sqrt(α) ∈ [0,1] (columns), the pair
//   E(μ)  = ∫ f cos θi dωi              the lobe's albedo with F = 1, and
//   E5(μ) = ∫ (1 − ωo·h)⁵ f cos θi dωi   its Schlick weight,
// so that the albedo of the lobe under Schlick's Fresnel F0 + (F90 − F0)(1 − ωo·h)⁵ is
// exactly F0 (E − E5) + F90 E5. A last row holds, per column, the cosine-weighted
// hemispherical averages 2∫ E(μ) μ dμ and 2∫ E5(μ) μ dμ of the *interpolated* rows, so
// that the compensation lobe built from them integrates to exactly what E lacks.
//
// After them, the rough dielectric's albedo (bsdf.h's reflection and transmission lobes
// with specular 1: Fd f_ss + etap² (1 − Fd) f_t) as pairs (E entering, E leaving), on a
// grid of kGlassAlbedoIors values of z = sqrt((ior − 1)/(ior + 1)) (up to
// kGlassAlbedoMaxIor), kGlassAlbedoCosines of sqrt(cos θ) and kGlassAlbedoRoughnesses of
// sqrt(roughness) (denser near 0, where the albedo at grazing angles falls fastest).
//
// VKPT_ALBEDO_PAIR(k) reads pair k. C++ reads the compiled-in array; a shader reads
// the same numbers from a texel buffer the host fills from it (lavapipe compiles a
// shader with an 8,320-float constant array for minutes).
#ifndef VKPT_GGX_ALBEDO_H
#define VKPT_GGX_ALBEDO_H
#include "layout.h"
#include "prelude.h"

#ifdef __cplusplus
#include "albedo_tables.h"
#endif

VKPT_BEGIN_NAMESPACE

// Bilinear lookup: (E, E5) at cos θ = mu for this alpha. Cells are found with int(),
// not uint(): lavapipe's compiler took minutes over a float-to-uint conversion whose
// result indexes a texel fetch.
VKPT_FN vec2 GgxAlbedo(float mu, float alpha) {
  float n = float(kGgxAlbedoSize - 1u);
  float x = sqrt(clamp(mu, 0.0f, 1.0f)) * n;
  float y = clamp(sqrt(alpha), 0.0f, 1.0f) * n;
  uint x0 = uint(clamp(int(x), 0, int(kGgxAlbedoSize) - 2));
  uint y0 = uint(clamp(int(y), 0, int(kGgxAlbedoSize) - 2));
  float fx = x - float(x0);
  float fy = y - float(y0);
  uint k00 = x0 * kGgxAlbedoSize + y0;
  uint k10 = k00 + kGgxAlbedoSize;
  vec2 a00 = VKPT_ALBEDO_PAIR(k00);
  vec2 a01 = VKPT_ALBEDO_PAIR(k00 + 1u);
  vec2 a10 = VKPT_ALBEDO_PAIR(k10);
  vec2 a11 = VKPT_ALBEDO_PAIR(k10 + 1u);
  return mix(mix(a00, a01, fy), mix(a10, a11, fy), fx);
}

// (E_avg, E5_avg) for this alpha, linear in sqrt(α) like the rows above.
VKPT_FN vec2 GgxAverageAlbedo(float alpha) {
  float y = clamp(sqrt(alpha), 0.0f, 1.0f) * float(kGgxAlbedoSize - 1u);
  uint y0 = uint(clamp(int(y), 0, int(kGgxAlbedoSize) - 2));
  float fy = y - float(y0);
  uint k0 = kGgxAlbedoSize * kGgxAlbedoSize + y0;
  vec2 a0 = VKPT_ALBEDO_PAIR(k0);
  vec2 a1 = VKPT_ALBEDO_PAIR(k0 + 1u);
  return mix(a0, a1, fy);
}

// The rough dielectric's albedo at cos θ = mu for this alpha and ior, from outside the
// volume (`entering`) or inside it: trilinear in (z, sqrt(μ), sqrt(roughness)).
VKPT_FN float GlassAlbedo(float mu, float alpha, float ior, bool entering) {
  float zMax = sqrt((kGlassAlbedoMaxIor - 1.0f) / (kGlassAlbedoMaxIor + 1.0f));
  float z = clamp(sqrt(max(ior - 1.0f, 0.0f) / (ior + 1.0f)) / zMax, 0.0f, 1.0f) * float(kGlassAlbedoIors - 1u);
  float x = sqrt(clamp(mu, 0.0f, 1.0f)) * float(kGlassAlbedoCosines - 1u);
  float y = sqrt(clamp(sqrt(alpha), 0.0f, 1.0f)) * float(kGlassAlbedoRoughnesses - 1u);
  uint z0 = uint(clamp(int(z), 0, int(kGlassAlbedoIors) - 2));
  uint x0 = uint(clamp(int(x), 0, int(kGlassAlbedoCosines) - 2));
  uint y0 = uint(clamp(int(y), 0, int(kGlassAlbedoRoughnesses) - 2));
  float fz = z - float(z0);
  float fx = x - float(x0);
  float fy = y - float(y0);
  uint r = kGlassAlbedoRoughnesses;
  uint k000 = kGgxAlbedoSize * (kGgxAlbedoSize + 1u) + (z0 * kGlassAlbedoCosines + x0) * r + y0;
  uint k100 = k000 + kGlassAlbedoCosines * r;
  vec2 e0 = mix(mix(VKPT_ALBEDO_PAIR(k000), VKPT_ALBEDO_PAIR(k000 + 1u), fy),
                mix(VKPT_ALBEDO_PAIR(k000 + r), VKPT_ALBEDO_PAIR(k000 + r + 1u), fy), fx);
  vec2 e1 = mix(mix(VKPT_ALBEDO_PAIR(k100), VKPT_ALBEDO_PAIR(k100 + 1u), fy),
                mix(VKPT_ALBEDO_PAIR(k100 + r), VKPT_ALBEDO_PAIR(k100 + r + 1u), fy), fx);
  vec2 e = mix(e0, e1, fz);
  return entering ? e.x : e.y;
}

VKPT_END_NAMESPACE

#endif

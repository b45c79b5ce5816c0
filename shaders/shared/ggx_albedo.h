// Directional albedo of the GGX lobe (microfacet.h), for energy compensation in bsdf.h.
//
// kGgxAlbedo (ggx_albedo_table.h, written by scripts/make_ggx_albedo_table.cpp) holds,
// on a kGgxAlbedoSize² grid over sqrt(cos θ) ∈ [0,1] (rows: E changes fastest at grazing
// angles) and roughness = sqrt(α) ∈ [0,1] (columns), the pair
//   E(μ)  = ∫ f cos θi dωi              the lobe's albedo with F = 1, and
//   E5(μ) = ∫ (1 − ωo·h)⁵ f cos θi dωi   its Schlick weight,
// so that the albedo of the lobe under Schlick's Fresnel F0 + (F90 − F0)(1 − ωo·h)⁵ is
// exactly F0 (E − E5) + F90 E5. A last row holds, per column, the cosine-weighted
// hemispherical averages 2∫ E(μ) μ dμ and 2∫ E5(μ) μ dμ of the *interpolated* rows, so
// that the compensation lobe built from them integrates to exactly what E lacks.
//
// VKPT_GGX_ALBEDO_PAIR(k) reads pair k. C++ reads the compiled-in array; a shader reads
// the same numbers from a texel buffer the host fills from it (lavapipe compiles a
// shader with an 8,320-float constant array for minutes).
#ifndef VKPT_GGX_ALBEDO_H
#define VKPT_GGX_ALBEDO_H
#include "layout.h"
#include "prelude.h"

#ifdef __cplusplus
#include "ggx_albedo_table.h"
static_assert(sizeof(vkpt::shader::kGgxAlbedo) ==
              2 * sizeof(float) * (vkpt::shader::kGgxAlbedoSize + 1) * vkpt::shader::kGgxAlbedoSize);
#define VKPT_GGX_ALBEDO_PAIR(k) vec2(kGgxAlbedo[2u * (k)], kGgxAlbedo[2u * (k) + 1u])
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
  vec2 a00 = VKPT_GGX_ALBEDO_PAIR(k00);
  vec2 a01 = VKPT_GGX_ALBEDO_PAIR(k00 + 1u);
  vec2 a10 = VKPT_GGX_ALBEDO_PAIR(k10);
  vec2 a11 = VKPT_GGX_ALBEDO_PAIR(k10 + 1u);
  return mix(mix(a00, a01, fy), mix(a10, a11, fy), fx);
}

// (E_avg, E5_avg) for this alpha, linear in sqrt(α) like the rows above.
VKPT_FN vec2 GgxAverageAlbedo(float alpha) {
  float y = clamp(sqrt(alpha), 0.0f, 1.0f) * float(kGgxAlbedoSize - 1u);
  uint y0 = uint(clamp(int(y), 0, int(kGgxAlbedoSize) - 2));
  float fy = y - float(y0);
  uint k0 = kGgxAlbedoSize * kGgxAlbedoSize + y0;
  vec2 a0 = VKPT_GGX_ALBEDO_PAIR(k0);
  vec2 a1 = VKPT_GGX_ALBEDO_PAIR(k0 + 1u);
  return mix(a0, a1, fy);
}

VKPT_END_NAMESPACE

#endif

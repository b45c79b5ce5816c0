// KHR_materials_sheen: the back-scattering of velvet-like fibres, a lobe laid over the
// metallic-roughness material (and under a clear coat):
//   f = sheenColor D(h) V(ωo, ωi) + f_base (1 − max(sheenColor) E(μo)),
// D the "Charlie" distribution and V the visibility term of Conty Estevez & Kulla 2017,
// "Production Friendly Microfacet Sheen BRDF" (the extension's implementation notes),
// α = sheenRoughness², and E(μ) the lobe's directional albedo with sheenColor 1, from a
// table. The base is scaled by the extension's view-only albedo scaling, so a white sheen
// over a lossless base returns what it receives (tested), as under the clear coat
// (clearcoat.h); the extension's other form, min over ωo and ωi, loses light.
//
// The table (kSheenAlbedo* in layout.h; scripts/make_sheen_albedo_table.cpp integrates it
// with this file's own lobe and sampler) holds E on a grid over sqrt(cos θ) ∈ [0, 1] and
// log α ∈ [log kMinSheenAlpha, 0] (the lobe's shape follows its exponent 1/α: a grid
// spaced in sheenRoughness instead interpolates 4× worse at small α), each
// pair the entries of two neighbouring α columns, so a bilinear lookup reads two pairs.
//
// E exceeds 1 at grazing angles for small α (up to 5.5 at μ 0.001, α 0.001: the fitted
// Λ is not a physical shadowing there). Where it does, the lobe is divided by E(μo) so it
// reflects no more than it receives, and the base is given nothing; elsewhere both are
// as the extension defines them.
#ifndef VKPT_SHEEN_H
#define VKPT_SHEEN_H
#include "prelude.h"  // first, as in every shared header

#include "layout.h"
#include "sampling.h"

#ifdef __cplusplus
#include "albedo_tables.h"
#endif

// A shader may define VKPT_SHEEN as a specialization constant that is false when no
// material has a sheen, so that lavapipe compiles no sheen lobe for such scenes.
#ifndef VKPT_SHEEN
#define VKPT_SHEEN true
#endif

VKPT_BEGIN_NAMESPACE

// The smallest α: D's exponent 1/α stays finite in binary32 (sin θ^1000 underflows only
// for θ below 40°, where D is negligible anyway).
const float kMinSheenAlpha = 1e-3f;

VKPT_FN float SheenAlpha(float roughness) { return max(roughness * roughness, kMinSheenAlpha); }

// D(h) = (2 + 1/α) sin^(1/α) θh / 2π: normalised, ∫ D cos θh dωh = 1.
VKPT_FN float SheenD(float cosH, float alpha) {
  float sin2 = max(1.0f - cosH * cosH, 0.0f);
  float invAlpha = 1.0f / alpha;
  return (2.0f + invAlpha) * pow(sin2, 0.5f * invAlpha) * (0.5f * kInvPi);
}

// The fit L(x) of the sheen's Λ, its five coefficients blended by (1 − α)².
VKPT_FN float SheenL(float x, float alpha) {
  float t = (1.0f - alpha) * (1.0f - alpha);
  float a = mix(21.5473f, 25.3245f, t);
  float b = mix(3.82987f, 3.32435f, t);
  float c = mix(0.19823f, 0.16801f, t);
  float d = mix(-1.97760f, -1.27393f, t);
  float e = mix(-4.32054f, -4.85967f, t);
  return a / (1.0f + b * pow(x, c)) + d * x + e;
}

VKPT_FN float SheenLambda(float cosTheta, float alpha) {
  return cosTheta < 0.5f ? exp(SheenL(cosTheta, alpha))
                         : exp(2.0f * SheenL(0.5f, alpha) - SheenL(1.0f - cosTheta, alpha));
}

// The lobe D V with sheenColor 1, V = 1 / ((1 + Λ(μo) + Λ(μi)) 4 μo μi); 0 unless both
// directions are above the surface.
VKPT_FN float EvalSheen(vec3 wo, vec3 wi, float alpha) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  vec3 h = normalize(wo + wi);
  float v = 1.0f / ((1.0f + SheenLambda(wo.z, alpha) + SheenLambda(wi.z, alpha)) * (4.0f * wo.z * wi.z));
  return SheenD(h.z, alpha) * v;
}

// The sampler. f cos θi = D(h) / (4 μo (1 + Λo + Λi)) is largest where the half vector
// lies near the horizon, which puts ωi near the horizon too, the more so the smaller α:
// sampling D's normals (sin θh = u^(1/(2 + 1/α))) and reflecting ωo sends most of them
// below the surface (0.3 % efficiency at α 0.01, μo 0.5). Instead cos θi is drawn with
// density ∝ (1 − cos θi)^m, m = 0.1/α, and φ uniformly: over α ∈ [0.01, 1] and μo ∈
// [0.05, 1] its efficiency E[w]² / E[w²] is 0.19–0.93, against 0–0.32 for D's normals
// and 0.003–0.80 for the cosine lobe (docs/design-notes.md, "Sheen").
VKPT_FN float SheenSamplerExponent(float alpha) { return 0.1f / alpha; }

VKPT_FN vec3 SampleSheen(float alpha, float u1, float u2) {
  float m = SheenSamplerExponent(alpha);
  float cosTheta = 1.0f - pow(u2, 1.0f / (m + 1.0f));
  float sinTheta = sqrt(max(1.0f - cosTheta * cosTheta, 0.0f));
  float phi = 2.0f * kPi * u1;
  return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

// The density with which SampleSheen finds ωi: (m + 1) (1 − cos θi)^m / 2π.
VKPT_FN float SheenPdf(vec3 wi, float alpha) {
  if (wi.z <= 0.0f) return 0.0f;
  float m = SheenSamplerExponent(alpha);
  return (m + 1.0f) * pow(max(1.0f - wi.z, 0.0f), m) * (0.5f * kInvPi);
}

// E(μ) for this α from the table, bilinear in (sqrt(μ), log α).
VKPT_FN float SheenAlbedo(float mu, float alpha) {
  float x = sqrt(clamp(mu, 0.0f, 1.0f)) * float(kSheenAlbedoCosines - 1u);
  float t = 1.0f - log(max(alpha, kMinSheenAlpha)) / log(kMinSheenAlpha);
  float y = clamp(t, 0.0f, 1.0f) * float(kSheenAlbedoRoughnesses - 1u);
  uint x0 = uint(clamp(int(x), 0, int(kSheenAlbedoCosines) - 2));
  uint y0 = uint(clamp(int(y), 0, int(kSheenAlbedoRoughnesses) - 2));
  uint k0 = kSheenAlbedoOffset + x0 * (kSheenAlbedoRoughnesses - 1u) + y0;
  vec2 e0 = VKPT_ALBEDO_PAIR(k0);
  vec2 e1 = VKPT_ALBEDO_PAIR(k0 + kSheenAlbedoRoughnesses - 1u);
  vec2 e = mix(e0, e1, x - float(x0));
  return mix(e.x, e.y, y - float(y0));
}

// The table's α for column j: kMinSheenAlpha^(1 − j / (columns − 1)).
VKPT_FN float SheenTableAlpha(uint j) {
  return pow(kMinSheenAlpha, 1.0f - float(j) / float(kSheenAlbedoRoughnesses - 1u));
}

VKPT_END_NAMESPACE

#endif

// The GGX (Trowbridge–Reitz) microfacet lobe with F = 1, in a shading frame whose normal
// is +z: distribution, height-correlated masking-shadowing and visible-normal sampling;
// isotropic (one α), and anisotropic (αx along the frame's x axis, αy along y; Heitz
// 2014, "Understanding the Masking-Shadowing Function", §5.3), whose functions take
// their isotropic form, bit for bit, where αx = αy.
//
// Numerics: D is written with sin²θ = x² + y² rather than 1 − cos²θ, so near-mirror
// lobes (α ≈ 1e-3) keep their peak instead of cancelling to noise; every square root
// is of a sum of non-negative terms.
#ifndef VKPT_MICROFACET_H
#define VKPT_MICROFACET_H
#include "prelude.h"
#include "sampling.h"

// A shader may define VKPT_ANISOTROPY as a specialization constant that is false when no
// material is anisotropic (KHR_materials_anisotropy), so that lavapipe compiles the
// isotropic lobe alone.
#ifndef VKPT_ANISOTROPY
#define VKPT_ANISOTROPY true
#endif

VKPT_BEGIN_NAMESPACE

// The smallest α used: roughness below ~0.032 is rendered as α = 1e-3, a mirror to the
// eye (the lobe is 0.06° wide) whose peak D = 1/(πα²) ≈ 3·10⁵ stays finite in binary32.
// A clamp, not a delta lobe, so that every surface takes part in MIS the same way.
const float kMinGgxAlpha = 1e-3f;

VKPT_FN float GgxAlpha(float roughness) { return max(roughness * roughness, kMinGgxAlpha); }

// D(h) = α² / (π (α² cos²θh + sin²θh)²) for a unit half vector h (Walter et al. 2007).
VKPT_FN float GgxD(vec3 h, float alpha) {
  float a2 = alpha * alpha;
  float d = a2 * h.z * h.z + (h.x * h.x + h.y * h.y);
  return a2 / (kPi * d * d);
}

// sqrt(α² + (1 − α²) cos²θ): the term both Smith functions below share.
VKPT_FN float GgxLambdaRoot(float cosTheta, float alpha) {
  float a2 = alpha * alpha;
  return sqrt(a2 + (1.0f - a2) * cosTheta * cosTheta);
}

// Height-correlated Smith visibility V = G2 / (4 cos θo cos θi) (Heitz 2014,
// "Understanding the Masking-Shadowing Function", eq. 99), for cosines > 0.
VKPT_FN float GgxVisibility(float cosO, float cosI, float alpha) {
  return 0.5f / (cosI * GgxLambdaRoot(cosO, alpha) + cosO * GgxLambdaRoot(cosI, alpha));
}

// The single-scattering lobe with F = 1: f = D(h) · V(ωo, ωi), for ωo, ωi above the
// surface; 0 below.
VKPT_FN float GgxReflection(vec3 wo, vec3 wi, float alpha) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  vec3 h = normalize(wo + wi);
  return GgxD(h, alpha) * GgxVisibility(wo.z, wi.z, alpha);
}

// Density of the reflected direction ωi = reflect(−ωo, h) when h is drawn from the
// visible normals of ωo: D_ωo(h) / (4 ωo·h) with D_ωo(h) = G1(ωo) max(0, ωo·h) D(h) / cos θo
// (Heitz 2018), which simplifies to D(h) / (2 (cos θo + sqrt(α² + (1 − α²) cos²θo))).
// A seam of the estimator (path.h): a test build may replace it.
#ifndef GgxReflectionPdf
VKPT_FN float GgxReflectionPdf(vec3 wo, vec3 wi, float alpha) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  vec3 h = normalize(wo + wi);
  return GgxD(h, alpha) / (2.0f * (wo.z + GgxLambdaRoot(wo.z, alpha)));
}
#endif

// A visible normal of ωo (cos θo > 0) from u ∈ [0,1)²: Dupuy & Benyoub 2023, "Sampling
// Visible GGX Normals with Spherical Caps" (HPG): in the configuration stretched to α = 1
// the visible normals are ωo plus a uniform point of the spherical cap z > −ωo.z.
VKPT_FN vec3 SampleGgxVisibleNormal(vec3 wo, float alpha, float u1, float u2) {
  vec3 v = normalize(vec3(alpha * wo.x, alpha * wo.y, wo.z));
  float phi = 2.0f * kPi * u1;
  float z = (1.0f - u2) * (1.0f + v.z) - v.z;
  float sinTheta = sqrt(max(0.0f, 1.0f - z * z));
  vec3 hStd = vec3(sinTheta * cos(phi), sinTheta * sin(phi), z) + v;
  return normalize(vec3(alpha * hStd.x, alpha * hStd.y, max(hStd.z, 0.0f)));
}

// Whether (αx, αy) is the isotropic lobe of α = αx.
VKPT_FN bool IsIsotropic(vec2 alpha) { return !VKPT_ANISOTROPY || alpha.x == alpha.y; }

// D(h) = 1 / (π αx αy (hx²/αx² + hy²/αy² + hz²)²).
VKPT_RARE_FN float GgxAnisotropicD(vec3 h, vec2 alpha) {
  float a2 = alpha.x * alpha.y;
  vec3 f = vec3(alpha.y * h.x, alpha.x * h.y, a2 * h.z);
  float w2 = a2 / dot(f, f);
  return a2 * w2 * w2 / kPi;
}

VKPT_FN float GgxD(vec3 h, vec2 alpha) { return IsIsotropic(alpha) ? GgxD(h, alpha.x) : GgxAnisotropicD(h, alpha); }

// sqrt(αx² x² + αy² y² + z²) for a unit direction w: the isotropic root at w's azimuth.
VKPT_FN float GgxLambdaRoot(vec3 w, vec2 alpha) {
  if (IsIsotropic(alpha)) return GgxLambdaRoot(w.z, alpha.x);
  return sqrt(alpha.x * alpha.x * w.x * w.x + alpha.y * alpha.y * w.y * w.y + w.z * w.z);
}

VKPT_RARE_FN float GgxAnisotropicVisibility(vec3 wo, vec3 wi, vec2 alpha) {
  return 0.5f / (abs(wi.z) * GgxLambdaRoot(wo, alpha) + wo.z * GgxLambdaRoot(wi, alpha));
}

// V for ωo above the surface and ωi on either side (|cos θi|).
VKPT_FN float GgxVisibility(vec3 wo, vec3 wi, vec2 alpha) {
  return IsIsotropic(alpha) ? GgxVisibility(wo.z, abs(wi.z), alpha.x) : GgxAnisotropicVisibility(wo, wi, alpha);
}

// GgxReflectionPdf's anisotropic form (apart, as that one is a seam).
VKPT_RARE_FN float GgxAnisotropicReflectionPdf(vec3 wo, vec3 wi, vec2 alpha) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  vec3 h = normalize(wo + wi);
  return GgxD(h, alpha) / (2.0f * (wo.z + GgxLambdaRoot(wo, alpha)));
}

// Stretched by (αx, αy) instead of α.
VKPT_RARE_FN vec3 SampleGgxAnisotropicVisibleNormal(vec3 wo, vec2 alpha, float u1, float u2) {
  vec3 v = normalize(vec3(alpha.x * wo.x, alpha.y * wo.y, wo.z));
  float phi = 2.0f * kPi * u1;
  float z = (1.0f - u2) * (1.0f + v.z) - v.z;
  float sinTheta = sqrt(max(0.0f, 1.0f - z * z));
  vec3 hStd = vec3(sinTheta * cos(phi), sinTheta * sin(phi), z) + v;
  return normalize(vec3(alpha.x * hStd.x, alpha.y * hStd.y, max(hStd.z, 0.0f)));
}

VKPT_FN vec3 SampleGgxVisibleNormal(vec3 wo, vec2 alpha, float u1, float u2) {
  return IsIsotropic(alpha) ? SampleGgxVisibleNormal(wo, alpha.x, u1, u2)
                            : SampleGgxAnisotropicVisibleNormal(wo, alpha, u1, u2);
}

VKPT_END_NAMESPACE

#endif

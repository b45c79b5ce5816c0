// The glTF 2.0 metallic-roughness BSDF (glTF spec Appendix B, with KHR_materials_ior and
// KHR_materials_specular), evaluated, sampled and given its pdf in a shading frame whose
// normal is +z. ωo points to the viewer, ωi to the light; both renderers run this code.
//
//   f = (1 − m) · dielectric + m · metal, m = metallic
//   metal      = Fm(ωo·h) f_ss + Fms_m f_ms                       Fm: Schlick, F0 = baseColor
//   dielectric = Fd(ωo·h) f_ss + Fms_d f_ms + baseColor/π · c(μo) c(μi)
//   Fd: Schlick with F0 = min(((ior − 1)/(ior + 1))² specularColor, 1) · specular and F90 = specular
//
// f_ss is the GGX lobe of microfacet.h (α = roughness², D·V). Two departures from the
// Appendix, both for energy conservation:
//  * Multiple scattering (Kulla & Conty 2017, "Revisiting Physically Based Shading at
//    Imageworks"): f_ms = (1 − E(μo))(1 − E(μi)) / (π (1 − E_avg)) returns exactly the
//    energy f_ss loses, scaled for Fresnel by Fms = F_avg² E_avg / (1 − F_avg (1 − E_avg))
//    with Schlick's F_avg = F0 + (F90 − F0)/21. A white metal then reflects everything at
//    every roughness (tested).
//  * The diffuse base is weighted by c(μ) = (1 − A(μ)) / sqrt(1 − A_avg), where A is the
//    albedo of the specular layer above it, instead of the Appendix's (1 − F(ωo·h)) per
//    direction pair, which creates energy at grazing angles (a white dielectric reflects
//    more than it receives). This albedo coupling (Kelemen & Szirmay-Kalos 2001; Kulla &
//    Conty 2017) is reciprocal and makes dielectric + diffuse sum to one for a white base.
//    A is scalar (the largest channel of F0), so no channel exceeds one.
// Lambert is the special case specular = 0, metallic = 0 (A = 0, f = baseColor/π).
//
// Sampling: one lobe chosen by its estimated albedo — the visible normals of GGX (Dupuy &
// Benyoub 2023) or the cosine hemisphere for diffuse and f_ms together — and the sample
// weighted by the mixture pdf of both (one-sample MIS, Veach 1997 §9.2.4), so each lane
// evaluates the same code whichever lobe it picked.
#ifndef VKPT_BSDF_H
#define VKPT_BSDF_H
#include "ggx_albedo.h"
#include "layout.h"
#include "microfacet.h"
#include "prelude.h"
#include "sampling.h"

// A shader may define VKPT_GLOSSY_MATERIALS as a specialization constant that is false
// when every material of the scene is Lambertian: lavapipe runs both sides of an `if`, so
// only a constant lets its compiler drop the GGX code (the Cornell box then costs what it
// did before this BSDF). The CPU decides per material.
#ifndef VKPT_GLOSSY_MATERIALS
#define VKPT_GLOSSY_MATERIALS true
#endif

VKPT_BEGIN_NAMESPACE

// A material prepared for one ωo: everything that does not depend on ωi.
struct Bsdf {
  vec3 baseColor;
  float metallic;
  vec3 f0;        // dielectric Schlick F0 (metals use baseColor)
  float f90;      // dielectric Schlick F90 (= specular)
  vec3 msWeight;  // (1 − m) Fms_d + m Fms_m: weight of f_ms
  float alpha;
  float albedoO;     // E(μo)
  float couplingO;   // c(μo) for the diffuse base (0 for metals)
  float invMsNorm;   // 1 / (π (1 − E_avg))
  float pSpecular;   // probability of sampling the GGX lobe
  float couplingF0;  // scalar layer albedo A(μ) = couplingF0 E + couplingE5 E5 + couplingMs
  float couplingE5;
  float couplingMs;
  float couplingNorm;  // 1 / sqrt(1 − A_avg)
  bool lambert;        // no specular layer, not metallic: f = baseColor/π, cosine sampling
};

struct BsdfSample {
  vec3 wi;
  float pdf;    // solid-angle density of the mixture; 0: no sample (below the surface)
  vec3 weight;  // f · cos θi / pdf
};

VKPT_FN vec3 SchlickFresnel(vec3 f0, vec3 f90, float cosTheta) {
  float m = clamp(1.0f - cosTheta, 0.0f, 1.0f);
  float m2 = m * m;
  return f0 + (f90 - f0) * (m2 * m2 * m);
}

// Kulla & Conty's Fresnel weight of the multiple-scattering lobe for Schlick F0, F90.
VKPT_FN vec3 MultipleScatteringFresnel(vec3 f0, vec3 f90, float eAvg) {
  vec3 fAvg = f0 + (f90 - f0) * (1.0f / 21.0f);
  return fAvg * fAvg * eAvg / (vec3(1.0f) - fAvg * (1.0f - eAvg));
}

// True for the Lambert special case (specular = 0, metallic = 0), where the full
// evaluation below would compute baseColor/π at many times the cost.
VKPT_FN bool IsLambertian(Material mat) { return mat.specular == 0.0f && mat.metallic == 0.0f; }

VKPT_FN Bsdf PrepareBsdf(Material mat, vec3 wo) {
  Bsdf b;
  b.baseColor = mat.baseColor;
  b.metallic = mat.metallic;
  b.lambert = !VKPT_GLOSSY_MATERIALS || IsLambertian(mat);
  if (b.lambert) return b;
  b.alpha = GgxAlpha(mat.roughness);
  float r = (mat.ior - 1.0f) / (mat.ior + 1.0f);
  b.f0 = min(r * r * mat.specularColor, vec3(1.0f)) * mat.specular;
  b.f90 = mat.specular;
  float mu = max(wo.z, 0.0f);
  vec2 e = GgxAlbedo(mu, b.alpha);  // (E, E5) at μo
  vec2 eAvg = GgxAverageAlbedo(b.alpha);
  b.albedoO = e.x;
  b.invMsNorm = kInvPi / max(1.0f - eAvg.x, 1e-6f);
  vec3 fmsD = MultipleScatteringFresnel(b.f0, vec3(b.f90), eAvg.x);
  vec3 fmsM = MultipleScatteringFresnel(b.baseColor, vec3(1.0f), eAvg.x);
  b.msWeight = mix(fmsD, fmsM, b.metallic);

  // The dielectric layer's scalar albedo A(μ) = F0s (E − E5) + F90 E5 + Fms_s (1 − E).
  float f0s = MaxComponent(b.f0);
  float fmsS = MaxComponent(fmsD);
  b.couplingF0 = f0s - fmsS;
  b.couplingE5 = b.f90 - f0s;
  b.couplingMs = fmsS;
  float aAvg = b.couplingF0 * eAvg.x + b.couplingE5 * eAvg.y + b.couplingMs;
  b.couplingNorm = inversesqrt(max(1.0f - aAvg, 1e-6f));
  float aO = b.couplingF0 * e.x + b.couplingE5 * e.y + b.couplingMs;
  b.couplingO = (1.0f - b.metallic) * max(1.0f - aO, 0.0f) * b.couplingNorm;

  // Lobe choice by estimated albedo at μo: the GGX lobe's is exact (F0 (E − E5) + F90 E5);
  // the cosine lobe carries f_ms and the diffuse base.
  vec3 specD = b.f0 * (e.x - e.y) + vec3(b.f90 * e.y);
  vec3 specM = b.baseColor * (e.x - e.y) + vec3(e.y);
  float wSpec = Luminance(mix(specD, specM, b.metallic));
  vec3 cosLobe = b.msWeight * (1.0f - e.x) + b.baseColor * (b.couplingO * b.couplingNorm);
  float wCos = Luminance(cosLobe);
  b.pSpecular = wSpec + wCos > 0.0f ? wSpec / (wSpec + wCos) : 0.5f;
  return b;
}

// f(ωo, ωi), without the cosine; 0 unless both directions are above the surface.
VKPT_FN vec3 EvalBsdf(Bsdf b, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return vec3(0.0f);
  if (b.lambert) return b.baseColor * kInvPi;
  vec3 h = normalize(wo + wi);
  float cosOH = dot(wo, h);
  vec3 fresnel =
      mix(SchlickFresnel(b.f0, vec3(b.f90), cosOH), SchlickFresnel(b.baseColor, vec3(1.0f), cosOH), b.metallic);
  vec3 f = fresnel * (GgxD(h, b.alpha) * GgxVisibility(wo.z, wi.z, b.alpha));
  vec2 ei = GgxAlbedo(wi.z, b.alpha);
  f += b.msWeight * ((1.0f - b.albedoO) * (1.0f - ei.x) * b.invMsNorm);
  float aI = b.couplingF0 * ei.x + b.couplingE5 * ei.y + b.couplingMs;
  float couplingI = max(1.0f - aI, 0.0f) * b.couplingNorm;
  f += b.baseColor * (kInvPi * b.couplingO * couplingI);
  return f;
}

VKPT_FN float BsdfPdf(Bsdf b, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  if (b.lambert) return CosineHemispherePdf(wi.z);
  return b.pSpecular * GgxReflectionPdf(wo, wi, b.alpha) + (1.0f - b.pSpecular) * CosineHemispherePdf(wi.z);
}

// u.x picks the lobe, (u.y, u.z) the direction within it (stratified over the pixel's
// samples). Both candidate directions are computed, so every lane runs the same code.
VKPT_FN BsdfSample SampleBsdf(Bsdf b, vec3 wo, vec3 u) {
  BsdfSample s;
  if (b.lambert) {
    s.wi = SampleCosineHemisphere(u.y, u.z);
    s.pdf = wo.z > 0.0f ? CosineHemispherePdf(s.wi.z) : 0.0f;
    s.weight = s.pdf > 0.0f ? b.baseColor : vec3(0.0f);
    return s;
  }
  vec3 h = SampleGgxVisibleNormal(wo, b.alpha, u.y, u.z);
  vec3 specular = 2.0f * dot(wo, h) * h - wo;
  vec3 diffuse = SampleCosineHemisphere(u.y, u.z);
  s.wi = u.x < b.pSpecular ? specular : diffuse;
  s.pdf = BsdfPdf(b, wo, s.wi);
  s.weight = s.pdf > 0.0f ? EvalBsdf(b, wo, s.wi) * (s.wi.z / s.pdf) : vec3(0.0f);
  return s;
}

VKPT_END_NAMESPACE

#endif

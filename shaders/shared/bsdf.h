// The glTF 2.0 metallic-roughness BSDF (glTF spec Appendix B, with KHR_materials_ior and
// KHR_materials_specular), evaluated, sampled and given its pdf in a shading frame whose
// normal is +z. ωo points to the viewer, ωi to the light; both renderers run this code.
//
//   f = (1 − m) · dielectric + m · metal, m = metallic, T = transmission
//   metal      = Fm(ωo·h) f_ss + Fms_m f_ms                       Fm: Schlick, F0 = baseColor
//   dielectric = (1 − T) [Fd(ωo·h) f_ss + Fms_d f_ms + baseColor/π · c(μo) c(μi)]
//                + T [Fd(ωo·h) f_ss + baseColor (1 − Fd(ωo·m)) f_t] / E_glass(μo)   (f_t: ωi below)
//   Fd: Schlick with F0 = min(((ior − 1)/(ior + 1))² specularColor, 1) · specular and F90 = specular
//
// KHR_materials_transmission replaces the share T of the diffuse base by the rough
// dielectric transmission f_t of transmission.h, tinted by baseColor; KHR_materials_volume
// decides whether it refracts (a volume's boundary, entered through the front face) or
// passes a thin wall. Inside a volume (etap < 1) Fd is Schlick at the cosine of the
// outer side, 1 under total internal reflection.
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
// Lambert is the special case specular = 0, metallic = 0, T = 0 (A = 0, f = baseColor/π).
//  * The transmissive share T (KHR_materials_transmission) is a rough dielectric whose
//    reflection Fd f_ss and transmission (1 − Fd) f_t are divided by their albedo at μo
//    (Turquin 2019, "Practical multiple scattering compensation for microfacet models",
//    as Blender 4 compensates glass): from a table over (μ, roughness, ior) for each side
//    of a volume's boundary (ggx_albedo.h, made by the same code), and E(μo) of the GGX
//    lobe for a thin wall, whose two lobes integrate to exactly that. A white rough
//    dielectric then returns what it receives from either side; f_ms covers the opaque
//    share alone. The scaling depends on μo only, so f is not reciprocal there.
//
// KHR_materials_diffuse_transmission passes the share dt of the diffuse base through the
// surface as a Lambertian lobe of diffuseTransmissionColor on the other side, weighted
// by the same coupling c(μo) c(|μi|), so it is reciprocal and a white base keeps its
// energy; transmission T, where both are present, takes its share first (the extension's
// mix(mix(diffuse_brdf, diffuse_btdf, dt), specular_btdf, T)).
//
// KHR_materials_sheen (sheen.h) lays a fibre lobe over all of this, the base weighted by
// 1 − max(sheenColor) E_s(μo), and KHR_materials_clearcoat (clearcoat.h) a GGX coat lobe
// over that, everything under it weighted by 1 − c A_c(μo).
//
// Sampling: one lobe chosen by its estimated albedo — the visible normals of GGX (Dupuy &
// Benyoub 2023) reflected or refracted, the coat's visible normals, the sheen's sampler,
// the cosine hemisphere for diffuse and f_ms together, or the cosine hemisphere below the
// surface for diffuse transmission — and the sample
// weighted by the mixture pdf of both (one-sample MIS, Veach 1997 §9.2.4), so each lane
// evaluates the same code whichever lobe it picked.
#ifndef VKPT_BSDF_H
#define VKPT_BSDF_H
#include "clearcoat.h"
#include "fresnel.h"
#include "ggx_albedo.h"
#include "layout.h"
#include "microfacet.h"
#include "prelude.h"
#include "sampling.h"
#include "sheen.h"
#include "transmission.h"

// A shader may define VKPT_DIFFUSE_TRANSMISSION as a specialization constant that is false
// when no material has KHR_materials_diffuse_transmission.
#ifndef VKPT_DIFFUSE_TRANSMISSION
#define VKPT_DIFFUSE_TRANSMISSION true
#endif

// A shader may define VKPT_GLOSSY_MATERIALS as a specialization constant that is false
// when every material the scene's triangles use is Lambertian (the default material the
// loader appends is a metal, used or not): lavapipe runs both sides of an `if`, so only a
// constant lets its compiler drop the GGX code. The CPU decides per material.
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
  vec3 msWeight;  // (1 − m − transmission) Fms_d + m Fms_m: weight of f_ms
  float alpha;
  float albedoO;     // E(μo)
  float couplingO;   // c(μo) for the diffuse base (0 for metals)
  float invMsNorm;   // 1 / (π (1 − E_avg))
  float pSpecular;   // probability of sampling the GGX lobe
  float couplingF0;  // scalar layer albedo A(μ) = couplingF0 E + couplingE5 E5 + couplingMs
  float couplingE5;
  float couplingMs;
  float couplingNorm;   // 1 / sqrt(1 − A_avg)
  float transmission;   // (1 − m) T: weight of the transmission lobe
  float glassScale;     // 1 / the rough dielectric's albedo at μo (1 without transmission)
  float pTransmission;  // probability of sampling it
  vec3 diffuseTransmissionColor;
  float diffuseTransmission;   // dt: the share of the diffuse base passed through (0: none)
  float pDiffuseTransmission;  // probability of sampling it
  float etap;                  // η beyond the surface / η on ωo's side; 1: thin wall (or no transmission)
  float coat;                  // KHR_materials_clearcoat's factor c (0: no coat)
  float coatAlpha;
  vec3 coatNormal;      // in this frame
  float coatBaseScale;  // 1 − c A_c(μo): the weight of everything under the coat
  float pCoat;          // probability of sampling the coat lobe
  vec3 sheenColor;      // KHR_materials_sheen's colour (0: no sheen)
  float sheenAlpha;
  float sheenScale;      // 1 / max(E_s(μo), 1): the sheen lobe reflects at most what it receives
  float sheenBaseScale;  // 1 − max(sheenColor) min(E_s(μo), 1): the weight of the base under it
  float pSheen;          // probability of sampling the sheen lobe
  bool lambert;          // no specular layer, not metallic, opaque: f = baseColor/π, cosine sampling
};

struct BsdfSample {
  vec3 wi;
  float pdf;    // solid-angle density of the mixture; 0: no sample (below the surface)
  vec3 weight;  // f · cos θi / pdf
};

// Kulla & Conty's Fresnel weight of the multiple-scattering lobe for Schlick F0, F90.
VKPT_FN vec3 MultipleScatteringFresnel(vec3 f0, vec3 f90, float eAvg) {
  vec3 fAvg = f0 + (f90 - f0) * (1.0f / 21.0f);
  return fAvg * fAvg * eAvg / (vec3(1.0f) - fAvg * (1.0f - eAvg));
}

// True for the Lambert special case (specular = 0, metallic = 0, transmission = 0, no
// coat, no sheen), where the full evaluation below would compute baseColor/π at many
// times the cost.
VKPT_FN bool IsLambertian(Material mat) {
  return mat.specular == 0.0f && mat.metallic == 0.0f && mat.transmission == 0.0f && mat.clearcoat == 0.0f &&
         MaxComponent(mat.sheenColor) == 0.0f && mat.diffuseTransmission == 0.0f;
}

// Whether the material passes light to the other side of its surface.
VKPT_FN bool Transmits(Bsdf b) { return b.transmission > 0.0f || b.diffuseTransmission > 0.0f; }

// The diffuse base's weights c(μ) (the coupling above): the dielectric layer's scalar
// albedo A(μ) = F0s (E − E5) + F90 E5 + Fms_s (1 − E), with E (e at μo, eAvg averaged)
// from the GGX table and the dielectric's Fms `fmsD`.
VKPT_FN void PrepareCoupling(VKPT_INOUT(Bsdf) b, vec2 e, vec2 eAvg, vec3 fmsD) {
  float f0s = MaxComponent(b.f0);
  float fmsS = MaxComponent(fmsD);
  b.couplingF0 = f0s - fmsS;
  b.couplingE5 = b.f90 - f0s;
  b.couplingMs = fmsS;
  float aAvg = b.couplingF0 * eAvg.x + b.couplingE5 * eAvg.y + b.couplingMs;
  b.couplingNorm = inversesqrt(max(1.0f - aAvg, 1e-6f));
  float aO = b.couplingF0 * e.x + b.couplingE5 * e.y + b.couplingMs;
  b.couplingO = (1.0f - b.metallic - b.transmission) * max(1.0f - aO, 0.0f) * b.couplingNorm;
}

// Lobe choice by estimated albedo at μo (e: the GGX table's (E, E5) there): the GGX
// lobe's is exact (F0 (E − E5) + F90 E5); the cosine lobe carries f_ms and the diffuse
// base; transmission ≈ (1 − Fd(μo)) E; the coat's is exact (c A_c), and it scales the
// others by what it leaves them. Inside a volume, Fd(μo) (1 past the critical angle)
// estimates both sides' shares, kept below 1 − α/2: microfacets tilted towards ωo
// transmit past the macroscopic critical angle, and a lobe that is never chosen would
// leave their light out (bias). The sheen's is exact (sheenColor min(E_s, 1), by
// luminance) and scales the base's, as the coat's scales all of them. Sets the sheen's
// and the coat's fields too.
VKPT_FN void ChooseLobes(VKPT_INOUT(Bsdf) b, Material mat, vec3 wo, vec2 e) {
  float mu = max(wo.z, 0.0f);
  vec3 specD = b.f0 * (e.x - e.y) + vec3(b.f90 * e.y);
  float fresnelO = MaxComponent(b.f0);
  if (b.etap < 1.0f) {
    fresnelO = min(MaxComponent(DielectricFresnel(b.f0, b.f90, mu, b.etap)), 1.0f - 0.5f * b.alpha);
    specD = vec3(fresnelO * e.x);
  }
  vec3 specM = b.baseColor * (e.x - e.y) + vec3(e.y);
  float wSpec = Luminance(mix(specD, specM, b.metallic));
  float diffuse = b.couplingO * b.couplingNorm;  // the diffuse base's albedo at μo
  vec3 cosLobe = b.msWeight * (1.0f - e.x) + b.baseColor * (diffuse * (1.0f - b.diffuseTransmission));
  float wCos = Luminance(cosLobe);
  float wTrans = b.transmission * b.glassScale * Luminance(b.baseColor) * (1.0f - fresnelO) * e.x;
  float wDiffuseTrans = Luminance(b.diffuseTransmissionColor) * (diffuse * b.diffuseTransmission);
  float wSheen = 0.0f;
  if (VKPT_SHEEN && MaxComponent(mat.sheenColor) > 0.0f) {
    b.sheenColor = mat.sheenColor;
    b.sheenAlpha = SheenAlpha(mat.sheenRoughness);
    float eSheen = SheenAlbedo(mu, b.sheenAlpha);
    b.sheenScale = 1.0f / max(eSheen, 1.0f);
    eSheen = min(eSheen, 1.0f);
    b.sheenBaseScale = 1.0f - MaxComponent(b.sheenColor) * eSheen;
    wSheen = Luminance(b.sheenColor) * eSheen;
    wSpec *= b.sheenBaseScale;
    wCos *= b.sheenBaseScale;
    wTrans *= b.sheenBaseScale;
    wDiffuseTrans *= b.sheenBaseScale;
  }
  float wCoat = 0.0f;
  if (VKPT_CLEARCOAT && mat.clearcoat > 0.0f) {
    b.coat = mat.clearcoat;
    b.coatAlpha = GgxAlpha(mat.clearcoatRoughness);
    wCoat = b.coat * CoatAlbedo(max(dot(wo, b.coatNormal), 0.0f), b.coatAlpha);
    b.coatBaseScale = 1.0f - wCoat;
    wSpec *= b.coatBaseScale;
    wCos *= b.coatBaseScale;
    wTrans *= b.coatBaseScale;
    wDiffuseTrans *= b.coatBaseScale;
    wSheen *= b.coatBaseScale;
  }
  float total = wSpec + wCos + wTrans + wDiffuseTrans + wSheen + wCoat;
  b.pSpecular = total > 0.0f ? wSpec / total : 0.5f;
  b.pTransmission = total > 0.0f ? wTrans / total : 0.0f;
  b.pDiffuseTransmission = total > 0.0f ? wDiffuseTrans / total : 0.0f;
  b.pSheen = total > 0.0f ? wSheen / total : 0.0f;
  b.pCoat = total > 0.0f ? wCoat / total : 0.0f;
}

// The material without any of the lobes PrepareBsdf adds: the Lambertian case complete,
// the rest to be filled in.
VKPT_FN Bsdf BaseBsdf(Material mat, vec3 coatNormal) {
  Bsdf b;
  b.baseColor = mat.baseColor;
  b.metallic = mat.metallic;
  b.lambert = !VKPT_GLOSSY_MATERIALS || IsLambertian(mat);
  b.transmission = 0.0f;
  b.pTransmission = 0.0f;
  b.diffuseTransmission = 0.0f;
  b.diffuseTransmissionColor = vec3(0.0f);
  b.pDiffuseTransmission = 0.0f;
  b.etap = 1.0f;
  b.glassScale = 1.0f;
  b.coat = 0.0f;
  b.coatAlpha = 1.0f;
  b.coatNormal = coatNormal;
  b.coatBaseScale = 1.0f;
  b.pCoat = 0.0f;
  b.sheenColor = vec3(0.0f);
  b.sheenAlpha = 1.0f;
  b.sheenScale = 1.0f;
  b.sheenBaseScale = 1.0f;
  b.pSheen = 0.0f;
  return b;
}

// `frontFace`: ωo lies on the side the surface's winding faces (outside a volume);
// `coatNormal`: the clear coat's normal in the shading frame (clearcoat.h).
VKPT_FN Bsdf PrepareBsdf(Material mat, vec3 wo, bool frontFace, vec3 coatNormal) {
  Bsdf b = BaseBsdf(mat, coatNormal);
  if (b.lambert) return b;
  b.transmission = (1.0f - mat.metallic) * mat.transmission;
  if (VKPT_DIFFUSE_TRANSMISSION) {
    b.diffuseTransmission = mat.diffuseTransmission;
    b.diffuseTransmissionColor = mat.diffuseTransmissionColor;
  }
  // A volume of ior 1 (or the ior-0 mirror) bends nothing: it is rendered as a thin wall.
  if (b.transmission > 0.0f && (mat.flags & kMaterialVolume) != 0u && mat.ior > 1.0f)
    b.etap = frontFace ? mat.ior : 1.0f / mat.ior;
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
  b.msWeight = mix(fmsD, fmsM, b.metallic) - b.transmission * fmsD;
  if (b.transmission > 0.0f) {
    float eGlass = b.etap == 1.0f ? e.x : GlassAlbedo(mu, b.alpha, mat.ior, b.etap > 1.0f);
    b.glassScale = 1.0f / max(eGlass, 1e-3f);
  }
  PrepareCoupling(b, e, eAvg, fmsD);
  ChooseLobes(b, mat, wo, e);
  return b;
}

// The transmission lobe T baseColor (1 − Fd) f_t / E_glass(μo) for ωi below the surface
// (wi.z < 0).
VKPT_FN vec3 EvalTransmission(Bsdf b, vec3 wo, vec3 wi) {
  float weight = b.transmission * b.glassScale;
  if (b.etap == 1.0f) {
    vec3 h = normalize(wo + MirrorThroughSurface(wi));
    vec3 f = vec3(1.0f) - DielectricFresnel(b.f0, b.f90, dot(wo, h), 1.0f);
    return (weight * GgxD(h, b.alpha) * GgxVisibility(wo.z, -wi.z, b.alpha)) * f * b.baseColor;
  }
  vec3 m = RefractionHalfVector(wo, wi, b.etap);
  if (m.z == 0.0f) return vec3(0.0f);
  vec3 f = vec3(1.0f) - DielectricFresnel(b.f0, b.f90, dot(wo, m), b.etap);
  return (weight * GgxRefraction(wo, wi, m, b.etap, b.alpha)) * f * b.baseColor;
}

// The diffuse base's albedo coupling c(|μi|) for ωi on either side, from the GGX table's
// (E, E5) at |μi|.
VKPT_FN float CouplingI(Bsdf b, float albedo, float albedo5) {
  float aI = b.couplingF0 * albedo + b.couplingE5 * albedo5 + b.couplingMs;
  return max(1.0f - aI, 0.0f) * b.couplingNorm;
}

// The diffuse transmission lobe dt diffuseTransmissionColor / π c(μo) c(|μi|) for ωi
// below the surface.
VKPT_FN vec3 EvalDiffuseTransmission(Bsdf b, vec3 wi) {
  vec2 ei = GgxAlbedo(-wi.z, b.alpha);
  float c = b.diffuseTransmission * kInvPi * b.couplingO * CouplingI(b, ei.x, ei.y);
  return b.diffuseTransmissionColor * c;
}

// f of everything under the coat, for ωo above the surface.
VKPT_FN vec3 EvalBase(Bsdf b, vec3 wo, vec3 wi) {
  if (wi.z < 0.0f) {
    vec3 t = b.transmission > 0.0f ? EvalTransmission(b, wo, wi) : vec3(0.0f);
    if (VKPT_DIFFUSE_TRANSMISSION && b.diffuseTransmission > 0.0f) t += EvalDiffuseTransmission(b, wi);
    return t;
  }
  vec3 h = normalize(wo + wi);
  float cosOH = dot(wo, h);
  vec3 fd = DielectricFresnel(b.f0, b.f90, cosOH, b.etap);
  // The transmissive share's reflection is scaled with its transmission (+0 when opaque).
  vec3 fresnel = mix(fd, SchlickFresnel(b.baseColor, vec3(1.0f), cosOH), b.metallic) +
                 fd * (b.transmission * (b.glassScale - 1.0f));
  vec3 f = fresnel * (GgxD(h, b.alpha) * GgxVisibility(wo.z, wi.z, b.alpha));
  vec2 ei = GgxAlbedo(wi.z, b.alpha);
  f += b.msWeight * ((1.0f - b.albedoO) * (1.0f - ei.x) * b.invMsNorm);
  float couplingI = CouplingI(b, ei.x, ei.y);
  f += b.baseColor * (kInvPi * b.couplingO * couplingI * (1.0f - b.diffuseTransmission));
  return f;
}

// f(ωo, ωi), without the cosine; 0 unless ωo is above the surface, and for ωi below it
// unless the material transmits.
VKPT_FN vec3 EvalBsdf(Bsdf b, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z == 0.0f) return vec3(0.0f);
  if (b.lambert) return wi.z > 0.0f ? b.baseColor * kInvPi : vec3(0.0f);
  vec3 f = EvalBase(b, wo, wi);
  if (VKPT_SHEEN && MaxComponent(b.sheenColor) > 0.0f)
    f = b.sheenBaseScale * f + b.sheenColor * (b.sheenScale * EvalSheen(wo, wi, b.sheenAlpha));
  if (VKPT_CLEARCOAT && b.coat > 0.0f)
    f = b.coatBaseScale * f + vec3(b.coat * EvalCoat(b.coatNormal, b.coatAlpha, wo, wi));
  return f;
}

VKPT_FN float TransmissionPdf(Bsdf b, vec3 wo, vec3 wi) {
  if (b.etap == 1.0f) return GgxReflectionPdf(wo, MirrorThroughSurface(wi), b.alpha);
  vec3 m = RefractionHalfVector(wo, wi, b.etap);
  return m.z == 0.0f ? 0.0f : GgxRefractionPdf(wo, wi, m, b.etap, b.alpha);
}

VKPT_FN float BsdfPdf(Bsdf b, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z == 0.0f) return 0.0f;
  if (wi.z < 0.0f) {
    float pdf = b.pTransmission > 0.0f ? b.pTransmission * TransmissionPdf(b, wo, wi) : 0.0f;
    if (VKPT_DIFFUSE_TRANSMISSION && b.pDiffuseTransmission > 0.0f)
      pdf += b.pDiffuseTransmission * CosineHemispherePdf(-wi.z);
    return pdf;
  }
  if (b.lambert) return CosineHemispherePdf(wi.z);
  float pdf =
      b.pSpecular * GgxReflectionPdf(wo, wi, b.alpha) +
      (1.0f - b.pSpecular - b.pTransmission - b.pDiffuseTransmission - b.pSheen - b.pCoat) * CosineHemispherePdf(wi.z);
  if (VKPT_SHEEN && b.pSheen > 0.0f) pdf += b.pSheen * SheenPdf(wi, b.sheenAlpha);
  if (VKPT_CLEARCOAT && b.pCoat > 0.0f) pdf += b.pCoat * CoatPdf(b.coatNormal, b.coatAlpha, wo, wi);
  return pdf;
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
  vec3 transmitted = b.etap == 1.0f ? MirrorThroughSurface(specular) : Refract(wo, h, b.etap);
  // A lobe's direction on the other lobe's side of the surface (a microfacet tilted past
  // it), or total internal reflection (Refract's zero vector), is no sample (wi = 0, pdf 0):
  // the pdf of a side counts only the lobes that sample it.
  if (specular.z <= 0.0f) specular = vec3(0.0f);
  if (transmitted.z >= 0.0f) transmitted = vec3(0.0f);
  vec3 coated = VKPT_CLEARCOAT && b.pCoat > 0.0f ? SampleCoat(b.coatNormal, b.coatAlpha, wo, u.y, u.z) : vec3(0.0f);
  vec3 sheen = VKPT_SHEEN && b.pSheen > 0.0f ? SampleSheen(b.sheenAlpha, u.y, u.z) : vec3(0.0f);
  // The lobes' shares of [0, 1) in order: specular, transmitted, diffusely transmitted,
  // coat, sheen, and the cosine lobe the rest.
  float pGlossy = b.pSpecular + b.pTransmission;
  float pThrough = pGlossy + b.pDiffuseTransmission;
  float pLayers = pThrough + b.pCoat + b.pSheen;
  vec3 layer = u.x < pThrough + b.pCoat ? coated : sheen;
  vec3 other = u.x < pThrough ? MirrorThroughSurface(diffuse) : (u.x < pLayers ? layer : diffuse);
  s.wi = u.x < b.pSpecular ? specular : (u.x < pGlossy ? transmitted : other);
  s.pdf = BsdfPdf(b, wo, s.wi);
  s.weight = s.pdf > 0.0f ? EvalBsdf(b, wo, s.wi) * (abs(s.wi.z) / s.pdf) : vec3(0.0f);
  return s;
}

VKPT_END_NAMESPACE

#endif

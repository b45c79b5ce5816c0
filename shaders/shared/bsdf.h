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
// KHR_materials_iridescence (iridescence.h) mixes a thin film's reflectance into Fd and
// Fm (and 1 − Fd of the transmission lobe), and scales the diffuse base by what the film
// changes in its layer's albedo at μo (bsdf_prepare.h's PrepareFilm).
//
// KHR_materials_anisotropy stretches the GGX lobe (reflected and transmitted) to
// αx = mix(α, 1, strength²) along the frame's x axis, the anisotropy's direction, and
// compensates it as the isotropic lobe of α = sqrt(αx αy) (bsdf_prepare.h).
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
// evaluates the same code whichever lobe it picked. The material's preparation for one ωo
// (struct Bsdf, the layers' weights and the lobes' probabilities) is bsdf_prepare.h's.
#ifndef VKPT_BSDF_H
#define VKPT_BSDF_H
#include "prelude.h"  // first, as in every shared header

#include "bsdf_prepare.h"
#include "clearcoat.h"
#include "fresnel.h"
#include "ggx_albedo.h"
#include "microfacet.h"
#include "sampling.h"
#include "sheen.h"
#include "transmission.h"

VKPT_BEGIN_NAMESPACE

struct BsdfSample {
  vec3 wi;
  float pdf;    // solid-angle density of the mixture; 0: no sample (below the surface)
  vec3 weight;  // f · cos θi / pdf
};

// The transmission lobe T baseColor (1 − Fd) f_t / E_glass(μo) for ωi below the surface
// (wi.z < 0).
VKPT_FN vec3 EvalTransmission(Bsdf b, vec3 wo, vec3 wi) {
  float weight = b.transmission * b.glassScale;
  if (b.etap == 1.0f) {
    vec3 h = normalize(wo + MirrorThroughSurface(wi));
    vec3 f = vec3(1.0f) - DielectricLayerFresnel(b, dot(wo, h));
    return (weight * GgxD(h, b.lobeAlpha) * GgxVisibility(wo, wi, b.lobeAlpha)) * f * b.baseColor;
  }
  vec3 m = RefractionHalfVector(wo, wi, b.etap);
  if (m.z == 0.0f) return vec3(0.0f);
  vec3 f = vec3(1.0f) - DielectricLayerFresnel(b, dot(wo, m));
  return (weight * GgxRefraction(wo, wi, m, b.etap, b.lobeAlpha)) * f * b.baseColor;
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
  vec3 fd = DielectricLayerFresnel(b, cosOH);
  // The transmissive share's reflection is scaled with its transmission (+0 when opaque).
  vec3 fresnel = mix(fd, MetalFresnel(b, cosOH), b.metallic) + fd * (b.transmission * (b.glassScale - 1.0f));
  vec3 f = fresnel * (GgxD(h, b.lobeAlpha) * GgxVisibility(wo, wi, b.lobeAlpha));
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

// The density of the GGX lobe's reflected ωi (above the surface).
VKPT_FN float SpecularPdf(Bsdf b, vec3 wo, vec3 wi) {
  return IsIsotropic(b.lobeAlpha) ? GgxReflectionPdf(wo, wi, b.alpha)
                                  : GgxAnisotropicReflectionPdf(wo, wi, b.lobeAlpha);
}

VKPT_FN float TransmissionPdf(Bsdf b, vec3 wo, vec3 wi) {
  if (b.etap == 1.0f) return SpecularPdf(b, wo, MirrorThroughSurface(wi));
  vec3 m = RefractionHalfVector(wo, wi, b.etap);
  return m.z == 0.0f ? 0.0f : GgxRefractionPdf(wo, wi, m, b.etap, b.lobeAlpha);
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
      b.pSpecular * SpecularPdf(b, wo, wi) +
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
  vec3 h = SampleGgxVisibleNormal(wo, b.lobeAlpha, u.y, u.z);
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

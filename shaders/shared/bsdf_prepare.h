// The glTF BSDF of bsdf.h prepared for one ωo: the struct Bsdf of everything that does
// not depend on ωi — the layers' weights (the diffuse base's albedo coupling, the
// transmissive share's albedo scaling, the sheen's and the coat's base scaling) and the
// probabilities with which SampleBsdf picks each lobe. bsdf.h says what the model is.
#ifndef VKPT_BSDF_PREPARE_H
#define VKPT_BSDF_PREPARE_H
#include "prelude.h"  // first, as in every shared header

#include "clearcoat.h"
#include "fresnel.h"
#include "ggx_albedo.h"
#include "iridescence.h"
#include "layout.h"
#include "microfacet.h"
#include "sampling.h"
#include "sheen.h"

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
  vec3 f0;           // dielectric Schlick F0 (metals use baseColor)
  float f90;         // dielectric Schlick F90 (= specular)
  vec3 msWeight;     // (1 − m − transmission) Fms_d + m Fms_m: weight of f_ms
  float alpha;       // the GGX lobe's α, or its anisotropic lobe's effective α for the albedo tables
  vec2 lobeAlpha;    // (αx, αy) along the frame's axes: (α, α) unless anisotropic
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
  float iridescence;     // KHR_materials_iridescence's weight (0: no film, or ωo inside a volume)
  float filmIor;
  float filmThickness;  // nm
  bool lambert;         // no specular layer, not metallic, opaque: f = baseColor/π, cosine sampling
};

// Kulla & Conty's Fresnel weight of the multiple-scattering lobe for Schlick F0, F90.
VKPT_FN vec3 MultipleScatteringFresnel(vec3 f0, vec3 f90, float eAvg) {
  vec3 fAvg = f0 + (f90 - f0) * (1.0f / 21.0f);
  return fAvg * fAvg * eAvg / (vec3(1.0f) - fAvg * (1.0f - eAvg));
}

// True for the Lambert special case (specular = 0, metallic = 0, transmission = 0, no
// coat, no sheen, no film), where the full evaluation below would compute baseColor/π at many
// times the cost.
VKPT_FN bool IsLambertian(Material mat) {
  return mat.specular == 0.0f && mat.metallic == 0.0f && mat.transmission == 0.0f && mat.clearcoat == 0.0f &&
         MaxComponent(mat.sheenColor) == 0.0f && mat.diffuseTransmission == 0.0f &&
         (mat.iridescence == 0.0f || mat.iridescenceThickness <= 0.0f);
}

// Whether the material passes light to the other side of its surface.
VKPT_FN bool Transmits(Bsdf b) { return b.transmission > 0.0f || b.diffuseTransmission > 0.0f; }

// The diffuse base's weights c(μ) (the coupling above): the dielectric layer's scalar
// albedo A(μ) = F0s (E − E5) + F90 E5 + Fms_s (1 − E), with E (e at μo, eAvg averaged)
// from the GGX table and the dielectric's Fms `fmsD`.
// The layer's albedo A at the GGX table's (E, E5) `e`, once PrepareCoupling has set its
// terms.
VKPT_FN float LayerAlbedo(Bsdf b, vec2 e) { return b.couplingF0 * e.x + b.couplingE5 * e.y + b.couplingMs; }

VKPT_FN void PrepareCoupling(VKPT_INOUT(Bsdf) b, vec2 e, vec2 eAvg, vec3 fmsD) {
  float f0s = MaxComponent(b.f0);
  float fmsS = MaxComponent(fmsD);
  b.couplingF0 = f0s - fmsS;
  b.couplingE5 = b.f90 - f0s;
  b.couplingMs = fmsS;
  b.couplingNorm = inversesqrt(max(1.0f - LayerAlbedo(b, eAvg), 1e-6f));
  float aO = LayerAlbedo(b, e);
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
  b.iridescence = 0.0f;
  b.filmIor = 1.0f;
  b.filmThickness = 0.0f;
  return b;
}

// Fresnel `f` at cos θ to a microfacet, mixed with the film's (iridescence.h) over a base
// of reflectance `baseF0` where the material has a film.
VKPT_FN vec3 WithFilm(Bsdf b, vec3 f, float cosTheta, vec3 baseF0) {
  if (VKPT_IRIDESCENCE && b.iridescence > 0.0f)
    f = mix(f, ThinFilmFresnel(cosTheta, b.filmIor, b.filmThickness, baseF0), b.iridescence);
  return f;
}

// The dielectric layer's Fresnel: Schlick's (DielectricFresnel) under the film.
VKPT_FN vec3 DielectricLayerFresnel(Bsdf b, float cosTheta) {
  return WithFilm(b, DielectricFresnel(b.f0, b.f90, cosTheta, b.etap), cosTheta, b.f0);
}

// The metal's: Schlick's with F0 = baseColor under the film on that F0.
VKPT_FN vec3 MetalFresnel(Bsdf b, float cosTheta) {
  return WithFilm(b, SchlickFresnel(b.baseColor, vec3(1.0f), cosTheta), cosTheta, b.baseColor);
}

// A film (iridescence.h) changes the dielectric layer's albedo at μo by what its Fresnel
// adds there, δ = (max F(μo) − max F_Schlick(μo)) E(μo): exact for a mirror (E = 1), an
// estimate for rough layers, whose Fresnel varies over the microfacets (within 2.2 % of
// the layer's albedo over roughness 0.3–1, tested). The diffuse base under it is scaled
// by (1 − A(μo) − δ) / (1 − A(μo)), as the extension weights it by 1 − max F, so it
// returns what the layer does not reflect. The coupling c(μi) stays Schlick's, so the
// scaling depends on μo only, as the sheen's does.
VKPT_RARE_FN void PrepareFilm(VKPT_INOUT(Bsdf) b, Material mat, float mu, vec2 e) {
  if (mat.iridescence <= 0.0f || mat.iridescenceThickness <= 0.0f || b.etap < 1.0f) return;
  b.iridescence = mat.iridescence;
  b.filmIor = mat.iridescenceIor;
  b.filmThickness = mat.iridescenceThickness;
  float schlick = MaxComponent(DielectricFresnel(b.f0, b.f90, mu, b.etap));
  float delta = (MaxComponent(DielectricLayerFresnel(b, mu)) - schlick) * e.x;
  float a = LayerAlbedo(b, e);
  b.couplingO *= max(1.0f - a - delta, 0.0f) / max(1.0f - a, 1e-6f);
}

// KHR_materials_anisotropy (αx along the frame's x axis, the anisotropy's direction;
// normal_map.h's AnisotropicFrame turns the frame so) is compensated as the isotropic
// lobe of α = sqrt(αx αy), the one of the same stretched area: the albedo tables, the
// multiple-scattering lobe and the diffuse coupling read it. The anisotropic lobe's
// albedo depends on ωo's azimuth too, which no isotropic α follows: a white anisotropic
// metal returns 0.93–1.03 at strength 0.5 and down to 0.58 at strength 1, where the lobe
// is as rough as can be along x (docs/limits.md). Larger effective α (the root mean
// square) lose less there but return up to 1.11 elsewhere, creating energy.
VKPT_FN float AnisotropicAlbedoAlpha(vec2 alpha) { return sqrt(alpha.x * alpha.y); }

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
  b.lobeAlpha = vec2(b.alpha);
  if (VKPT_ANISOTROPY && mat.anisotropy > 0.0f) {
    b.lobeAlpha.x = mix(b.alpha, 1.0f, mat.anisotropy * mat.anisotropy);
    b.alpha = AnisotropicAlbedoAlpha(b.lobeAlpha);
  }
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
  if (VKPT_IRIDESCENCE) PrepareFilm(b, mat, mu, e);
  ChooseLobes(b, mat, wo, e);
  return b;
}

VKPT_END_NAMESPACE

#endif

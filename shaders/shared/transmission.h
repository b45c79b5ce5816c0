// Transmission through a rough dielectric boundary, with the GGX microfacets of
// microfacet.h, in a shading frame whose normal is +z and faces ωo (wo.z > 0). The
// transmitted direction ωi lies below (wi.z < 0). F is the Fresnel reflectance of the
// microfacet, so each lobe below carries the (1 − F) that is not reflected.
//
// Two boundaries, as KHR_materials_volume distinguishes them:
//  * A volume's boundary (Walter et al. 2007, "Microfacet Models for Refraction through
//    Rough Surfaces", eqs. 21 and 38, in pbrt-v4's form): ωi bends by Snell's law with
//    etap = η(ωi's side) / η(ωo's side).
//  * A thin wall (etap = 1): light crosses two parallel boundaries and leaves in the
//    direction it came, blurred by the roughness; modelled as the reflection lobe mirrored
//    through the surface plane (ωi → (ωi.x, ωi.y, −ωi.z)), so that it samples and
//    integrates exactly like the reflection it mirrors.
#ifndef VKPT_TRANSMISSION_H
#define VKPT_TRANSMISSION_H
#include "microfacet.h"
#include "prelude.h"

VKPT_BEGIN_NAMESPACE

// The direction ωo refracts into through a microfacet of normal m (ωo·m > 0), or the zero
// vector under total internal reflection.
VKPT_FN vec3 Refract(vec3 wo, vec3 m, float etap) {
  float cosO = dot(wo, m);
  float sin2T = max(0.0f, 1.0f - cosO * cosO) / (etap * etap);
  if (sin2T >= 1.0f) return vec3(0.0f);
  float cosT = sqrt(1.0f - sin2T);
  return (cosO / etap - cosT) * m - wo / etap;
}

// The microfacet normal that refracts ωo into ωi (the generalized half vector,
// Walter eq. 16), facing +z; the zero vector when no microfacet seen from both
// directions does (ωi on the wrong side of it).
VKPT_FN vec3 RefractionHalfVector(vec3 wo, vec3 wi, float etap) {
  vec3 m = etap * wi + wo;
  float len2 = dot(m, m);
  if (!(len2 > 0.0f)) return vec3(0.0f);
  m *= inversesqrt(len2);
  if (m.z < 0.0f) m = -m;
  if (dot(m, wo) <= 0.0f || dot(m, wi) >= 0.0f) return vec3(0.0f);
  return m;
}

// ωi mirrored through the surface plane: the thin wall's transmitted direction ↔ the
// reflected one.
VKPT_FN vec3 MirrorThroughSurface(vec3 w) { return vec3(w.x, w.y, -w.z); }

// Walter's BTDF without Fresnel, for radiance: f_t = (1 − F(ωo·m)) · this, with
// 4 |ωi·m| |ωo·m| D V / (etap ωi·m + ωo·m)² = ηo² |ωi·m||ωo·m| D G / (|cos θi cos θo| (ηi ωi·m + ηo ωo·m)²)
// (pbrt-v4's DielectricBxDF after its radiance scaling by 1/etap²). It satisfies
// f(ωo, ωi) / ηo² = f(ωi, ωo) / ηi² (Veach 1997, §5.2; tested).
VKPT_FN float GgxRefraction(vec3 wo, vec3 wi, vec3 m, float etap, float alpha) {
  float denom = etap * dot(wi, m) + dot(wo, m);
  return 4.0f * abs(dot(wi, m) * dot(wo, m)) * GgxD(m, alpha) * GgxVisibility(wo.z, -wi.z, alpha) / (denom * denom);
}

// Density of ωi = Refract(ωo, m, etap) when m is drawn from the visible normals of ωo:
// D_ωo(m) |dm/dωi| with |dm/dωi| = etap² |ωi·m| / (etap ωi·m + ωo·m)² (Walter eq. 17).
VKPT_FN float GgxRefractionPdf(vec3 wo, vec3 wi, vec3 m, float etap, float alpha) {
  float denom = etap * dot(wi, m) + dot(wo, m);
  float visibleD = 2.0f * dot(wo, m) * GgxD(m, alpha) / (wo.z + GgxLambdaRoot(wo.z, alpha));
  return visibleD * etap * etap * abs(dot(wi, m)) / (denom * denom);
}

// The anisotropic lobe's (microfacet.h).
VKPT_RARE_FN float GgxAnisotropicRefraction(vec3 wo, vec3 wi, vec3 m, float etap, vec2 alpha) {
  float denom = etap * dot(wi, m) + dot(wo, m);
  return 4.0f * abs(dot(wi, m) * dot(wo, m)) * GgxD(m, alpha) * GgxVisibility(wo, wi, alpha) / (denom * denom);
}

VKPT_FN float GgxRefraction(vec3 wo, vec3 wi, vec3 m, float etap, vec2 alpha) {
  return IsIsotropic(alpha) ? GgxRefraction(wo, wi, m, etap, alpha.x)
                            : GgxAnisotropicRefraction(wo, wi, m, etap, alpha);
}

VKPT_RARE_FN float GgxAnisotropicRefractionPdf(vec3 wo, vec3 wi, vec3 m, float etap, vec2 alpha) {
  float denom = etap * dot(wi, m) + dot(wo, m);
  float visibleD = 2.0f * dot(wo, m) * GgxD(m, alpha) / (wo.z + GgxLambdaRoot(wo, alpha));
  return visibleD * etap * etap * abs(dot(wi, m)) / (denom * denom);
}

VKPT_FN float GgxRefractionPdf(vec3 wo, vec3 wi, vec3 m, float etap, vec2 alpha) {
  return IsIsotropic(alpha) ? GgxRefractionPdf(wo, wi, m, etap, alpha.x)
                            : GgxAnisotropicRefractionPdf(wo, wi, m, etap, alpha);
}

VKPT_END_NAMESPACE

#endif

// KHR_materials_clearcoat: a clear dielectric GGX layer (ior 1.5, so F0 = 0.04 and
// F90 = 1) over the whole material, with its own factor c, roughness and normal. The
// extension's specification layers it as
//   f = c F_c(ωo·h) f_coat + (1 − c F_c) f_base,   Le dimmed to (1 − c F_c(n_c·ωo)) Le.
// vkpt weighs the base by 1 − c A_c(μo) instead, A_c being the coat lobe's directional
// albedo at μo = n_c·ωo from the GGX table (the albedo scaling of Kulla & Conty 2017 and
// Turquin 2019, as Blender and the Enterprise PBR model layer a coat): the coat lobe
// reflects c A_c(μo) of the light arriving along ωo, and the base is given exactly the
// rest, so a white coat over a lossless base returns what it receives (tested), where
// the specification's F_c(ωo·h) would weigh the base by the Fresnel of each microfacet
// pair instead of what the layer reflects on average.
//
// The coat's Fresnel (kCoatF0, CoatFresnel) and the emission it dims (CoatTransmittance)
// are fresnel.h's, which the estimator reads without the lobe.
//
// The coat's normal n_c is given in the base's shading frame (bsdf.h works in it): the
// vertex normal, or the coat's own normal texture, where the base may be normal-mapped.
// The coat lobe is a reflection on both the base's and the coat's side.
#ifndef VKPT_CLEARCOAT_H
#define VKPT_CLEARCOAT_H
#include "prelude.h"  // first, as in every shared header

#include "fresnel.h"
#include "ggx_albedo.h"
#include "microfacet.h"
#include "sampling.h"

// A shader may define VKPT_CLEARCOAT as a specialization constant that is false when no
// material has a clear coat, so that lavapipe compiles no coat lobe for such scenes.
#ifndef VKPT_CLEARCOAT
#define VKPT_CLEARCOAT true
#endif

VKPT_BEGIN_NAMESPACE

// A_c(μ) = ∫ F_c D V cos θi dωi = F0 (E − E5) + E5 from the GGX table.
VKPT_FN float CoatAlbedo(float mu, float alpha) {
  vec2 e = GgxAlbedo(mu, alpha);
  return kCoatF0 * (e.x - e.y) + e.y;
}

// The coat lobe F_c(ωo·h) D(h) V(ωo, ωi) for normal `n`, without the factor c: 0 unless ωo
// and ωi are above both the coat (n) and the base (+z).
VKPT_FN float EvalCoat(vec3 n, float alpha, vec3 wo, vec3 wi) {
  Frame f = FrameFromNormal(n);
  vec3 o = WorldToFrame(f, wo);
  vec3 i = WorldToFrame(f, wi);
  if (o.z <= 0.0f || i.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  vec3 h = normalize(o + i);
  return CoatFresnel(dot(o, h)) * GgxD(h, alpha) * GgxVisibility(o.z, i.z, alpha);
}

// The density with which SampleCoat finds ωi.
VKPT_FN float CoatPdf(vec3 n, float alpha, vec3 wo, vec3 wi) {
  if (wi.z <= 0.0f) return 0.0f;
  Frame f = FrameFromNormal(n);
  return GgxReflectionPdf(WorldToFrame(f, wo), WorldToFrame(f, wi), alpha);
}

// ωo reflected about a visible normal of the coat, or the zero vector (no sample) where
// that leaves below the coat or the base.
VKPT_FN vec3 SampleCoat(vec3 n, float alpha, vec3 wo, float u1, float u2) {
  Frame f = FrameFromNormal(n);
  vec3 o = WorldToFrame(f, wo);
  if (o.z <= 0.0f) return vec3(0.0f);
  vec3 h = SampleGgxVisibleNormal(o, alpha, u1, u2);
  vec3 r = 2.0f * dot(o, h) * h - o;
  vec3 wi = FrameToWorld(f, r);
  return r.z > 0.0f && wi.z > 0.0f ? wi : vec3(0.0f);
}

VKPT_END_NAMESPACE

#endif

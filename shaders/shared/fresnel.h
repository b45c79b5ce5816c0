// Schlick's Fresnel approximation (Schlick 1994, "An Inexpensive BRDF Model for
// Physically-based Rendering"), as the glTF BSDF (bsdf.h) and its albedo tables
// (scripts/make_ggx_albedo_table.cpp) use it.
#ifndef VKPT_FRESNEL_H
#define VKPT_FRESNEL_H
#include "prelude.h"

VKPT_BEGIN_NAMESPACE

VKPT_FN vec3 SchlickFresnel(vec3 f0, vec3 f90, float cosTheta) {
  float m = clamp(1.0f - cosTheta, 0.0f, 1.0f);
  float m2 = m * m;
  return f0 + (f90 - f0) * (m2 * m2 * m);
}

// Fd for a microfacet at cosine cosTheta to ωo, on a boundary of relative index etap:
// from the denser side (etap < 1) Schlick's approximation holds at the refracted cosine
// (Schlick 1994 is written for the side of the smaller index), and F = 1 past the
// critical angle.
VKPT_FN vec3 DielectricFresnel(vec3 f0, float f90, float cosTheta, float etap) {
  if (etap < 1.0f) {
    float sin2T = (1.0f - cosTheta * cosTheta) / (etap * etap);
    if (sin2T >= 1.0f) return vec3(1.0f);
    cosTheta = sqrt(1.0f - sin2T);
  }
  return SchlickFresnel(f0, vec3(f90), cosTheta);
}

// KHR_materials_clearcoat's coat (clearcoat.h) is a dielectric of ior 1.5: F0 =
// ((1.5 − 1) / (1.5 + 1))² = 0.04 and F90 = 1.
const float kCoatF0 = 0.04f;

VKPT_FN float CoatFresnel(float cosTheta) { return SchlickFresnel(vec3(kCoatF0), vec3(1.0f), cosTheta).x; }

// The share of an emitter's radiance that leaves through its coat (factor c) at cos θ
// from its normal: 1 − c F_c(cos θ), as the extension dims emission. Both strategies of
// MIS take cos θ from the emitter's geometric normal (shading_frame.h, lights.h).
VKPT_FN float CoatTransmittance(float coat, float cosTheta) { return 1.0f - coat * CoatFresnel(abs(cosTheta)); }

VKPT_END_NAMESPACE

#endif

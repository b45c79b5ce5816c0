// Test-only replacements for the seams of the shared estimator (shaders/shared/path.h
// says what a seam is), for the CPU variants (tests/path_variant.cpp) and the GPU mutant
// kernels (tests/CMakeLists.txt). A build that defines VKPT_ESTIMATOR_OVERRIDES and puts
// this folder on its include path gets this header first from path.h; each macro below
// selects replacements (several may be combined, e.g. a mutant with BSDF sampling alone):
//
// The MIS strategies alone, for comparison with MIS (tests/test_mis.cpp):
//   VKPT_MIS_LIGHT_ONLY  light sampling alone: light that light sampling can reach
//                        counts nothing when a BSDF-sampled ray finds it
//   VKPT_MIS_BSDF_ONLY   BSDF sampling alone (delta lights keep light sampling)
// Mutants: deliberately wrong estimators that a test must reject.
//   VKPT_MUTANT_MIS_WEIGHT_ONE           both strategies count in full: double counting
//   VKPT_MUTANT_MIS_SWAPPED_PDFS         the light sample's weight with its pdfs swapped
//                                        (swapped on both sides the weights would still
//                                        sum to one, and the estimator stay unbiased)
//   VKPT_MUTANT_GGX_PDF_NO_JACOBIAN      GgxReflectionPdf without the 1/(4 ωo·h) of reflection
//   VKPT_MUTANT_ROULETTE_WITHOUT_DIVISION a surviving path not divided by its survival probability
//   VKPT_MUTANT_NO_LIGHT_COSINE          a light sample forgets cos θ' at the emitter
//   VKPT_MUTANT_LIGHT_SAMPLE_WITHOUT_TEXTURE  the emissive factor taken for the emission at
//                                        a sampled point, its texture ignored
//   VKPT_MUTANT_TEXTURES_FILTERED_EVERYWHERE  every texture read at its ray cone's level at
//                                        every vertex, normal maps and roughness too
//   VKPT_MUTANT_LIGHT_SAMPLE_WITHOUT_COAT  a sampled point's emission not dimmed by its
//                                        clear coat
//   VKPT_MUTANT_WAVELENGTH_WEIGHT_EVERY_VERTEX  the hero wavelength's colour weight applied
//                                        at every dispersive vertex, not once per path
// and mutants of the punctual lights, which tests/test_light_transport.cpp's closed
// forms must reject:
//   VKPT_MUTANT_SPOT_FALLOFF_LINEAR      the cone's falloff not squared
//   VKPT_MUTANT_RANGE_WINDOW_SQUARED     the range window squared (the window of Frostbite
//                                        and Unreal, not the extension's)
//   VKPT_MUTANT_POINT_NO_INVERSE_SQUARE  point and spot lights without 1/r²
//   VKPT_MUTANT_DIRECTIONAL_EXTRA_COSINE a directional light's E already times cos θ,
//                                        which the estimator then counts again
// The mutants that only CPU variants use are C++ only ((void) for unused parameters).
#ifndef VKPT_ESTIMATOR_OVERRIDES_H
#define VKPT_ESTIMATOR_OVERRIDES_H
#if defined(VKPT_MICROFACET_H) || defined(VKPT_BSDF_H) || defined(VKPT_LIGHTS_H)
#error "estimator_overrides.h comes too late: a header whose seams it replaces is already in"
#endif
#include "shared/prelude.h"  // first, as in every shared header

#include "shared/layout.h"
#include "shared/sampling.h"

#if defined(VKPT_MUTANT_GGX_PDF_NO_JACOBIAN)
#define GgxReflectionPdf GgxHalfVectorPdf
#endif
#include "shared/microfacet.h"  // for GgxD and GgxLambdaRoot; without GgxReflectionPdf if replaced

VKPT_BEGIN_NAMESPACE

#if defined(VKPT_MIS_LIGHT_ONLY) || defined(VKPT_MUTANT_MIS_WEIGHT_ONE)
#define LightSampleWeight LightSampleWeightWhole
VKPT_FN float LightSampleWeightWhole(float lightPdf, float bsdfPdf) {
  (void)bsdfPdf;
  return lightPdf > 0.0f ? 1.0f : 0.0f;
}
#elif defined(VKPT_MIS_BSDF_ONLY)
#define LightSampleWeight LightSampleWeightNone
VKPT_FN float LightSampleWeightNone(float lightPdf, float bsdfPdf) {
  (void)lightPdf;
  return bsdfPdf > 0.0f ? 0.0f : 1.0f;
}
#elif defined(VKPT_MUTANT_MIS_SWAPPED_PDFS)
#define LightSampleWeight LightSampleWeightSwapped
VKPT_FN float LightSampleWeightSwapped(float lightPdf, float bsdfPdf) { return PowerHeuristic(bsdfPdf, lightPdf); }
#endif

#if defined(VKPT_MIS_BSDF_ONLY) || defined(VKPT_MUTANT_MIS_WEIGHT_ONE)
#define BsdfSampleWeight BsdfSampleWeightWhole
VKPT_FN float BsdfSampleWeightWhole(float bsdfPdf, float lightPdf) {
  (void)lightPdf;
  return bsdfPdf > 0.0f ? 1.0f : 0.0f;
}
#elif defined(VKPT_MIS_LIGHT_ONLY)
#define BsdfSampleWeight BsdfSampleWeightNone
VKPT_FN float BsdfSampleWeightNone(float bsdfPdf, float lightPdf) {
  (void)bsdfPdf;
  return lightPdf > 0.0f ? 0.0f : 1.0f;
}
#endif

#ifdef VKPT_MUTANT_GGX_PDF_NO_JACOBIAN
// D_ωo(h), the density of the half vector, for that of the reflected direction.
VKPT_FN float GgxHalfVectorPdf(vec3 wo, vec3 wi, float alpha) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  vec3 h = normalize(wo + wi);
  return 2.0f * dot(wo, h) * GgxD(h, alpha) / (wo.z + GgxLambdaRoot(wo.z, alpha));
}
#endif

#ifdef VKPT_MUTANT_ROULETTE_WITHOUT_DIVISION
#define RouletteSurvivorThroughput RouletteSurvivorThroughputUndivided
// GLSL only (the GPU mutant): C++ would warn of the unused parameter.
VKPT_FN vec3 RouletteSurvivorThroughputUndivided(vec3 throughput, float survive) { return throughput; }
#endif

#ifdef VKPT_MUTANT_NO_LIGHT_COSINE
#define EmitterCosine EmitterCosineOne
VKPT_FN float EmitterCosineOne(Light l, vec3 wi) {
  float cosLight = -dot(l.direction, wi);
  if (l.type == kLightTwoSidedTriangle) cosLight = abs(cosLight);
  return cosLight > 0.0f ? 1.0f : cosLight;
}
#endif

#ifdef VKPT_MUTANT_LIGHT_SAMPLE_WITHOUT_TEXTURE
#define EmissionTextureAt EmissionTextureIgnored
VKPT_FN vec3 EmissionTextureIgnored(VKPT_SCENE_PARAM Material mat, uint material, uint sourceIndex, vec2 b) {
  (void)scene, (void)mat, (void)material, (void)sourceIndex, (void)b;
  return vec3(1.0f);
}
#endif

#ifdef VKPT_MUTANT_TEXTURES_FILTERED_EVERYWHERE
#define TextureCones TextureConesEverywhere
VKPT_FN vec2 TextureConesEverywhere(FrameParams params, uint bounce, float coneWidth) {
  (void)bounce;
  return vec2(params.textureLod != 0u ? coneWidth : 0.0f);
}
#endif

#ifdef VKPT_MUTANT_LIGHT_SAMPLE_WITHOUT_COAT
#define EmitterCoatTransmittance EmitterCoatIgnored
VKPT_FN float EmitterCoatIgnored(VKPT_SCENE_PARAM Material mat, uint material, uint sourceIndex, vec2 b,
                                 float cosLight) {
  (void)scene, (void)mat, (void)material, (void)sourceIndex, (void)b, (void)cosLight;
  return 1.0f;
}
#endif

#ifdef VKPT_MUTANT_SPOT_FALLOFF_LINEAR
#define SpotFalloff SpotFalloffLinear
VKPT_FN float SpotFalloffLinear(Light l, vec3 wiFromLight) {
  float cd = dot(l.direction, wiFromLight);
  float scale = 1.0f / max(0.001f, l.cosInner - l.cosOuter);
  return clamp((cd - l.cosOuter) * scale, 0.0f, 1.0f);
}
#endif

#ifdef VKPT_MUTANT_RANGE_WINDOW_SQUARED
#define RangeFalloff RangeFalloffSquared
VKPT_FN float RangeFalloffSquared(float range, float dist) {
  if (range <= 0.0f) return 1.0f;
  float x = dist / range;
  float x2 = x * x;
  float window = clamp(1.0f - x2 * x2, 0.0f, 1.0f);
  return window * window;
}
#endif

#ifdef VKPT_MUTANT_POINT_NO_INVERSE_SQUARE
// A macro, for RangeFalloff comes later (lights.h).
#define PunctualFalloff(range, dist, dist2) RangeFalloff(range, dist)
#endif

#ifdef VKPT_MUTANT_DIRECTIONAL_EXTRA_COSINE
// E times cos θ at the shading point: a macro, for it reads SampleLi's locals p and
// origin (origin − p leaves on the geometric normal's side, along it on an axis-aligned
// surface).
#define DirectionalIrradiance(l) ((l).radiance * max(dot(-(l).direction, normalize(origin - p)), 0.0f))
#endif

VKPT_END_NAMESPACE

#ifdef VKPT_MUTANT_WAVELENGTH_WEIGHT_EVERY_VERTEX
#define DrawsWavelength DrawsWavelengthEveryVertex
VKPT_FN bool DrawsWavelengthEveryVertex(float wavelength) {
  (void)wavelength;
  return true;
}
#endif

#endif

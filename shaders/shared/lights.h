// Light sampling for next-event estimation, and the density of a direction that BSDF
// sampling found a light along (for multiple importance sampling). Every light of the
// scene — emissive triangles, KHR_lights_punctual point, spot and directional lights and
// the environment map — is one entry of one table, chosen with probability ∝ its estimated power
// (host/render/light_table.cpp). In a scene with many finite lights (emissive triangles,
// point and spot lights) the table's share of those lights goes to the light tree
// (light_tree.h), which divides it among them by their importance at the shading point.
//
// Units: emission is radiance; a punctual light's intensity (candela in glTF) is radiant
// intensity I and a directional light's (lux) irradiance E, 1:1, so a point light of
// intensity I lights a Lambert surface at distance r to ρ/π · I cos θ / r².
//
// Scene access (backend_contract.h): VKPT_TRIANGLE(i), VKPT_LIGHT(i), VKPT_LIGHT_CDF(i) and
// light_tree.h's,
// environment.h's VKPT_ENV_TEXEL(i), VKPT_ENV_CDF(i), and material_textures.h's.
//
// The punctual falloffs and the emitter's cosine, texture and clear coat below are seams
// of the estimator (path.h): a test build may replace them.
#ifndef VKPT_LIGHTS_H
#define VKPT_LIGHTS_H
#include "alpha.h"
#include "environment.h"
#include "estimator.h"
#include "fresnel.h"
#include "intersect.h"
#include "layout.h"
#include "light_tree.h"
#include "material_textures.h"
#include "prelude.h"
#include "sampling.h"

// A shader may define VKPT_LIGHT_TYPES as a specialization constant: the set of light
// types in the scene's light table (bit 1 << kLight*), 0 without lights. lavapipe runs an
// if's body even when no lane takes it, so only a constant lets its compiler drop the
// code of the types a scene lacks (the Cornell box: all but triangles, whose sampling
// then costs what it did before punctual lights and environment maps). The CPU branches.
#ifndef VKPT_LIGHT_TYPES
#define VKPT_LIGHT_TYPES 0xFFFFFFFFu
#endif

VKPT_BEGIN_NAMESPACE

VKPT_FN bool SceneHasLightType(uint type) { return (VKPT_LIGHT_TYPES & (1u << type)) != 0u; }
const uint kTriangleLightTypes = (1u << kLightTriangle) | (1u << kLightTwoSidedTriangle);

struct LightSample {
  vec3 wi;        // unit direction from the shading point to the light
  float pdf;      // solid-angle density, light choice included; for delta lights the choice's pmf
  vec3 radiance;  // Li arriving along ωi (delta lights: I·falloff/r² or E, to divide by pdf alike)
  bool delta;     // a point, spot or directional light: no BSDF sample can hit it
  Ray shadowRay;  // must be unoccluded for t < shadowTMax
  float shadowTMax;
};

// The light table's CDF search (sampling.h).
VKPT_DEFINE_CDF_SEARCH(FindLightInterval, VKPT_LIGHT_CDF)

struct LightChoice {
  uint light;  // index into the light table
  float pmf;   // the probability of choosing it
  float u;     // the random number, stretched back to [0,1) within the choice
};

// Chooses a light for the shading point p (unit geometric normal n) with u ∈ [0,1): the
// light whose CDF interval holds u (smallest k with u < cdf[k]), or, where u falls in the
// tree's lights [0, params.treeLights), the tree's choice among them. The stretched u is
// pbrt-v4's SampleDiscrete: the point on a triangle light stays stratified over the union
// of all triangles.
VKPT_FN LightChoice ChooseLight(VKPT_SCENE_PARAM FrameParams params, vec3 p, vec3 n, float u) {
  LightChoice c;
  uint first = 0u;
  if (VKPT_LIGHT_TREE && params.treeLights > 0u) {
    float treeShare = VKPT_LIGHT_CDF(params.treeLights - 1u);
    if (u < treeShare) {
      LightTreeChoice t = SampleLightTree(VKPT_SCENE_ARG params.treeLights, treeShare, p, n, u);
      c.light = t.light;
      c.pmf = t.pmf;
      c.u = t.u;
      return c;
    }
    first = params.treeLights;
  }
  c.light = FindLightInterval(VKPT_SCENE_ARG first, params.lightCount - first, u) + first;
  Light l = VKPT_LIGHT(c.light);
  float cdfBelow = c.light > 0u ? VKPT_LIGHT_CDF(c.light - 1u) : 0.0f;
  c.pmf = l.pmf;
  c.u = min((u - cdfBelow) / (l.cdf - cdfBelow), kOneMinusEpsilon);
  return c;
}

// The probability that ChooseLight picks light k (`l`) for the shading point p, n.
VKPT_FN float LightChoicePmf(VKPT_SCENE_PARAM FrameParams params, uint k, Light l, vec3 p, vec3 n) {
  if (VKPT_LIGHT_TREE && k < params.treeLights)
    return LightTreePmf(VKPT_SCENE_ARG params.treeLights, VKPT_LIGHT_CDF(params.treeLights - 1u), p, n, k);
  return l.pmf;
}

// Solid-angle density of reaching a point of emissive triangle light `l`, chosen with
// probability `pmf`, at distance `dist` along a direction making cosine `cosLight` with
// its normal: pmf · dist² / (area cos θ').
VKPT_FN float TriangleLightPdf(Light l, float pmf, float dist, float cosLight) {
  return cosLight > 0.0f ? pmf * dist * dist / (l.extent * cosLight) : 0.0f;
}

// KHR_lights_punctual's spot cone: smoothstep-free quadratic falloff between the outer
// and inner cone, as the extension's reference implementation computes it. A seam.
#ifndef SpotFalloff
VKPT_FN float SpotFalloff(Light l, vec3 wiFromLight) {
  float cd = dot(l.direction, wiFromLight);
  float scale = 1.0f / max(0.001f, l.cosInner - l.cosOuter);
  float a = clamp((cd - l.cosOuter) * scale, 0.0f, 1.0f);
  return a * a;
}
#endif

// KHR_lights_punctual's recommended range window, clamp(1 − (dist/range)⁴, 0, 1): 1 at
// the light, 0 from `range` on. Unsquared, unlike the windows of Frostbite and Unreal. A
// seam.
#ifndef RangeFalloff
VKPT_FN float RangeFalloff(float range, float dist) {
  if (range <= 0.0f) return 1.0f;
  float x = dist / range;
  float x2 = x * x;
  return clamp(1.0f - x2 * x2, 0.0f, 1.0f);
}
#endif

// What reaches distance `dist` (dist2 = dist²) of a point or spot light per unit of its
// intensity: the inverse-square law, times the range window. A seam.
#ifndef PunctualFalloff
VKPT_FN float PunctualFalloff(float range, float dist, float dist2) { return RangeFalloff(range, dist) / dist2; }
#endif

// A directional light's irradiance, given (as glTF gives it, in lux) on a surface facing
// the light: the estimator's cos θ at the shading point (path.h) makes it the irradiance
// of a surface at any angle. A seam.
#ifndef DirectionalIrradiance
VKPT_FN vec3 DirectionalIrradiance(Light l) { return l.radiance; }
#endif

// cos θ' at a point of triangle light `l` seen along wi (unit, towards the light): ≤ 0
// where its emitting side faces away, unless it emits from both sides. A seam.
#ifndef EmitterCosine
VKPT_FN float EmitterCosine(Light l, vec3 wi) {
  float cosLight = -dot(l.direction, wi);
  return l.type == kLightTwoSidedTriangle ? abs(cosLight) : cosLight;
}
#endif

// The emissive texture of material `mat` (index `material`) at barycentrics b of source
// triangle `sourceIndex`, which a ray hitting that point would find (shading_frame.h);
// 1 where the material has none. A seam.
#ifndef EmissionTextureAt
VKPT_FN vec3 EmissionTextureAt(VKPT_SCENE_PARAM Material mat, uint material, uint sourceIndex, vec2 b) {
  if ((mat.flags & kMaterialTextured) == 0u) return vec3(1.0f);
  return EmissiveTexture(VKPT_SCENE_ARG material, sourceIndex, b.x, b.y);
}
#endif

// The share of the emission at barycentrics b of source triangle `sourceIndex` (material
// `mat`, index `material`) that leaves through the material's clear coat at cos θ' =
// cosLight, as a ray hitting that point finds it (shading_frame.h). A seam.
#ifndef EmitterCoatTransmittance
VKPT_FN float EmitterCoatTransmittance(VKPT_SCENE_PARAM Material mat, uint material, uint sourceIndex, vec2 b,
                                       float cosLight) {
  return CoatTransmittance(EmitterCoat(VKPT_SCENE_ARG mat.clearcoat, mat.flags, material, sourceIndex, b.x, b.y),
                           cosLight);
}
#endif

// The radiance of triangle light `l` (triangle `tri`) at barycentrics b towards cos θ' =
// cosLight, as a ray hitting that point would find it (shading_frame.h), so that both
// strategies of multiple importance sampling estimate the same integrand: its emissive
// texture, its clear coat's dimming, and, where alpha leaves part of the emitter out, its
// coverage (a ray finds that part with that probability).
VKPT_FN vec3 EmissionAt(VKPT_SCENE_PARAM Light l, Triangle tri, vec2 b, float cosLight) {
  vec3 radiance = l.radiance;
  if (VKPT_TEXTURES || VKPT_ALPHA || VKPT_CLEARCOAT) {
    Material mat = VKPT_MATERIAL(tri.material);
    if (VKPT_TEXTURES) radiance *= EmissionTextureAt(VKPT_SCENE_ARG mat, tri.material, tri.sourceIndex, b);
    if (VKPT_ALPHA) radiance *= Coverage(VKPT_SCENE_ARG mat, tri.material, tri.sourceIndex, b.x, b.y);
    if (VKPT_CLEARCOAT && mat.clearcoat > 0.0f)
      radiance *= EmitterCoatTransmittance(VKPT_SCENE_ARG mat, tri.material, tri.sourceIndex, b, cosLight);
  }
  return radiance;
}

// Samples a light for the shading point p (unit geometric normal n), whose rays leave from
// `origin` (p offset along the geometric normal on the side the path arrived from;
// path.h moves a shadow ray that goes through the surface to the other side), with u ∈
// [0,1)²: u.x chooses the light (ChooseLight) and, stretched, with u.y the point on it.
// pdf = 0: no contribution.
VKPT_FN LightSample SampleLi(VKPT_SCENE_PARAM FrameParams params, vec3 p, vec3 n, vec3 origin, vec2 u) {
  LightChoice choice = ChooseLight(VKPT_SCENE_ARG params, p, n, u.x);
  Light l = VKPT_LIGHT(choice.light);
  u.x = choice.u;
  LightSample ls;
  // Constant where the scene has triangle lights only, so that lavapipe compiles no branch.
  bool triangle = (VKPT_LIGHT_TYPES & ~kTriangleLightTypes) == 0u || l.type <= kLightTwoSidedTriangle;
  ls.pdf = 0.0f;  // stays so only for a type outside VKPT_LIGHT_TYPES, which cannot occur
  ls.delta = !triangle;
  ls.shadowRay.origin = origin;
  ls.shadowTMax = 1.0f;
  if ((VKPT_LIGHT_TYPES & kTriangleLightTypes) != 0u && triangle) {
    Triangle tri = VKPT_TRIANGLE(l.triangle);
    vec2 b = SampleUniformTriangle(u.x, u.y);
    vec3 x = tri.v0 + b.x * tri.e1 + b.y * tri.e2;
    vec3 nl = l.direction;
    vec3 d = x - p;
    float dist = length(d);
    ls.wi = d / dist;
    float cosLight = EmitterCosine(l, ls.wi);
    ls.pdf = TriangleLightPdf(l, choice.pmf, dist, cosLight);
    ls.radiance = EmissionAt(VKPT_SCENE_ARG l, tri, b, cosLight);
    // Aim at the light point lifted off the emitter towards p, with tMax = 1 on the
    // unnormalised direction: the emitter itself then lies beyond tMax.
    ls.shadowRay.dir = OffsetRayOrigin(x, dot(nl, p - x) > 0.0f ? nl : -nl) - origin;
  } else if (SceneHasLightType(kLightEnvironment) && l.type == kLightEnvironment) {
    EnvSample es = SampleEnvironment(VKPT_SCENE_ARG params, u);
    ls.wi = es.dir;
    ls.pdf = choice.pmf * es.pdf;
    ls.radiance = es.radiance;
    ls.delta = false;
    ls.shadowRay.dir = ls.wi;
    ls.shadowTMax = kInfinity;
  } else if (SceneHasLightType(kLightDirectional) && l.type == kLightDirectional) {
    ls.wi = -l.direction;
    ls.pdf = choice.pmf;
    ls.radiance = DirectionalIrradiance(l);
    ls.shadowRay.dir = ls.wi;
    ls.shadowTMax = kInfinity;
  } else if (SceneHasLightType(kLightPoint) || SceneHasLightType(kLightSpot)) {  // point or spot
    vec3 d = l.position - p;
    float dist2 = dot(d, d);
    float dist = sqrt(dist2);
    ls.wi = d / dist;
    float falloff = PunctualFalloff(l.extent, dist, dist2);
    if (SceneHasLightType(kLightSpot) && l.type == kLightSpot) falloff *= SpotFalloff(l, -ls.wi);
    ls.pdf = dist2 > 0.0f ? choice.pmf : 0.0f;
    ls.radiance = l.radiance * falloff;
    ls.shadowRay.dir = l.position - origin;
  }
  return ls;
}

VKPT_END_NAMESPACE

#endif

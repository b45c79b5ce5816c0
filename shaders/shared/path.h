// The path-tracing estimator, one source for both renderers.
//
// Path tracing with next-event estimation and Russian roulette (GAMES101 lecture 16,
// `shade(p, wo)`; Kajiya 1986). At every path vertex, direct light is estimated by
// sampling a point on an emissive triangle (area sampling, dω = cos θ' dA / r²), and
// the path continues along a cosine-weighted direction. Emission is added only where
// the camera ray hits an emitter directly; light reaching later vertices is counted by
// the light samples, so nothing is counted twice. Rays that escape collect the constant
// environment radiance (FrameParams::background), which is never light-sampled. All
// surfaces are Lambertian, f = ρ/π.
//
// Each side supplies scene access before including this file, so that traversal stays
// separate (the CPU walks the BVH with an ordered stack, the shader stackless):
//   VKPT_SCENE_PARAM          a leading parameter declaration ("" in GLSL)
//   VKPT_SCENE_ARG            the matching leading argument ("" in GLSL)
//   VKPT_TRIANGLE(i), VKPT_MATERIAL(i), VKPT_EMITTER(i)   element access
//   HitRecord TraceClosest(VKPT_SCENE_PARAM vec3 origin, vec3 dir, float tMax)
//   bool TraceOccluded(VKPT_SCENE_PARAM vec3 origin, vec3 dir, float tMax)
#ifndef VKPT_PATH_H
#define VKPT_PATH_H
#include "prelude.h"
#include "layout.h"
#include "rng.h"
#include "sampling.h"
#include "intersect.h"
#include "estimator.h"

// A shader may define VKPT_LIGHT_SAMPLING as a specialization constant that is false
// when the scene has no emitters: lavapipe runs an if's body even when no lane takes it,
// so the constant lets its compiler drop the light-sampling code.
#ifndef VKPT_LIGHT_SAMPLING
#define VKPT_LIGHT_SAMPLING true
#endif

VKPT_BEGIN_NAMESPACE

// The emitter whose CDF interval holds u ∈ [0,1): smallest k with u < cdf[k].
VKPT_FN uint PickEmitter(VKPT_SCENE_PARAM uint count, float u) {
  uint lo = 0u;
  uint hi = count - 1u;
  while (lo < hi) {
    uint mid = (lo + hi) / 2u;
    if (u < VKPT_EMITTER(mid).cdf) hi = mid;
    else lo = mid + 1u;
  }
  return lo;
}

struct PathSample {
  vec3 radiance;
  uint rays;  // closest-hit plus shadow rays traced
};

// A path under construction: the ray about to be traced from its latest vertex and, when
// that vertex sampled a light, the shadow ray still to be traced. The path is built one
// ray at a time (ShadeHit after a closest hit, AddLightIfVisible after a shadow ray) so
// that a SIMD lane can trace whichever ray it has next, and start its next sample as soon
// as a path ends, instead of idling while its neighbours' rays go on (path regeneration,
// Novák et al. 2010). The CPU calls the same steps in order (TracePath).
struct PathState {
  Ray ray;             // the next closest-hit ray: camera ray, then bounce directions
  vec3 throughput;
  PathSample result;   // what the path has gathered so far
  uint bounce;         // vertices found so far
  uint pixel;          // py * width + px
  uint sampleIndex;
  bool shadowPending;  // a light sample awaits its shadow ray (shadowRay, tMax = 1)
  Ray shadowRay;
  vec3 lightContribution;  // added to the radiance if the shadow ray is unoccluded
};

// Sample `sampleIndex` of pixel (px, py) before its first ray: the camera ray. Its random
// numbers come from the streams (params.seed, pixel, sampleIndex, dimension).
VKPT_FN PathState StartPath(FrameParams params, uint px, uint py, uint sampleIndex) {
  PathState s;
  s.pixel = py * params.width + px;
  s.sampleIndex = sampleIndex;
  vec2 uc = Sample2D(params.seed, s.pixel, sampleIndex, kGroupCamera);
  s.ray = GenerateCameraRay(params, px, py, uc.x, uc.y);
  s.throughput = vec3(1.0f);
  s.result.radiance = vec3(0.0f);
  s.result.rays = 1u;  // the camera ray
  s.bounce = 0u;
  s.shadowPending = false;
  s.shadowRay = s.ray;
  s.lightContribution = vec3(0.0f);
  return s;
}

// Next-event estimation at vertex `bounce` (at p, shading normal n, reflectance
// baseColor): samples a point on an emitter and, if it can contribute, sets the shadow
// ray from `origin` to it and the contribution it carries if unoccluded.
VKPT_FN void SampleLight(VKPT_SCENE_PARAM FrameParams params, VKPT_INOUT(PathState) s, uint bounce, vec3 p, vec3 n,
                         vec3 origin, vec3 baseColor) {
  // One stratified 2-D sample picks the emitter *and* the point on it: us.x chooses
  // the CDF interval and is then stretched back to [0,1) within it (pbrt-v4's
  // SampleDiscrete remapping). The points thus stay stratified over the union of all
  // emitters (a quad light's two triangles, say), not just within the one picked.
  vec2 us = Sample2D(params.seed, s.pixel, s.sampleIndex, LightGroup(bounce));
  uint k = PickEmitter(VKPT_SCENE_ARG params.emitterCount, us.x);
  Emitter e = VKPT_EMITTER(k);
  float cdfBelow = k > 0u ? VKPT_EMITTER(k - 1u).cdf : 0.0f;
  us.x = min((us.x - cdfBelow) / (e.cdf - cdfBelow), kOneMinusEpsilon);
  Triangle light = VKPT_TRIANGLE(e.triangle);
  Material lightMat = VKPT_MATERIAL(light.material);
  vec2 b = SampleUniformTriangle(us.x, us.y);
  vec3 x = light.v0 + b.x * light.e1 + b.y * light.e2;
  vec3 nl = normalize(cross(light.e1, light.e2));
  bool twoSided = (lightMat.flags & kMaterialDoubleSided) != 0u;
  float w = LightSampleWeight(p, n, x, nl, twoSided, e.pmf, e.area);
  if (w > 0.0f) {
    // Aim at the light point lifted off the emitter towards p, with tMax = 1 on the
    // unnormalised direction: the emitter itself then lies beyond tMax.
    vec3 target = OffsetRayOrigin(x, dot(nl, p - x) > 0.0f ? nl : -nl);
    s.result.rays += 1u;
    s.shadowPending = true;
    s.shadowRay.origin = origin;
    s.shadowRay.dir = target - origin;
    s.lightContribution = s.throughput * (baseColor * kInvPi) * lightMat.emission * w;
  }
}

// The path's ray s.ray has found `hit`: adds what is seen there, samples a light (setting
// s.shadowPending and the shadow ray if the sample can contribute) and the continuation
// s.ray. Returns false if no further closest-hit ray follows (the pending shadow ray, if
// any, must still be resolved before the path's radiance is final).
VKPT_FN bool ShadeHit(VKPT_SCENE_PARAM FrameParams params, VKPT_INOUT(PathState) s, HitRecord hit) {
  uint bounce = s.bounce;
  s.bounce = bounce + 1u;
  if (hit.t < 0.0f) {
    s.result.radiance += s.throughput * params.background;
    return false;
  }
  Triangle tri = VKPT_TRIANGLE(hit.triangle);
  Material mat = VKPT_MATERIAL(tri.material);
  vec3 ng = normalize(cross(tri.e1, tri.e2));
  bool frontFace = dot(ng, s.ray.dir) < 0.0f;
  if (bounce == 0u && (frontFace || (mat.flags & kMaterialDoubleSided) != 0u))
    s.result.radiance += s.throughput * mat.emission;
  // Paths have at most maxDepth bounces: the light sample at vertex k, and the ray
  // leaving it (which may escape to the environment), make k + 1.
  if (bounce >= params.maxDepth) return false;

  // Surfaces reflect on both sides: shade with the normal facing the incoming ray.
  vec3 n = frontFace ? ng : -ng;
  vec3 p = tri.v0 + hit.b1 * tri.e1 + hit.b2 * tri.e2;
  vec3 baseColor = mat.baseColor;
  vec3 origin = OffsetRayOrigin(p, n);

  vec4 ul = Random4(params.seed, s.pixel, s.sampleIndex, LightGroup(bounce));
  if (VKPT_LIGHT_SAMPLING && params.emitterCount > 0u && MaxComponent(baseColor) > 0.0f)
    SampleLight(VKPT_SCENE_ARG params, s, bounce, p, n, origin, baseColor);

  // Cosine-weighted bounce: f·cos θ / pdf = (ρ/π)·cos θ / (cos θ/π) = ρ.
  s.throughput *= baseColor;
  // Russian roulette (GAMES101: continue with probability P, divide by P): survival
  // follows the throughput, so dim paths end early and bright ones rarely.
  if (bounce >= params.rrDepth) {
    float survive = min(1.0f, MaxComponent(s.throughput));
    if (!(ul.w < survive)) return false;
#ifndef VKPT_MUTANT_ROULETTE_WITHOUT_DIVISION
    s.throughput /= survive;
#endif
  }
  vec2 ub = Sample2D(params.seed, s.pixel, s.sampleIndex, BsdfGroup(bounce));
  s.ray.origin = origin;
  s.ray.dir = FrameToWorld(FrameFromNormal(n), SampleCosineHemisphere(ub.x, ub.y));
  s.result.rays += 1u;
  return true;
}

// The pending shadow ray has been traced: the light sample counts if nothing blocked it.
VKPT_FN void AddLightIfVisible(VKPT_INOUT(PathState) s, bool occluded) {
  s.shadowPending = false;
  if (!occluded) s.result.radiance += s.lightContribution;
}

// Radiance carried by sample `sampleIndex` of pixel (px, py): one whole path.
VKPT_FN PathSample TracePath(VKPT_SCENE_PARAM FrameParams params, uint px, uint py, uint sampleIndex) {
  PathState s = StartPath(params, px, py, sampleIndex);
  bool more = true;
  while (more) {
    HitRecord hit = TraceClosest(VKPT_SCENE_ARG s.ray.origin, s.ray.dir, kInfinity);
    more = ShadeHit(VKPT_SCENE_ARG params, s, hit);
    if (s.shadowPending)
      AddLightIfVisible(s, TraceOccluded(VKPT_SCENE_ARG s.shadowRay.origin, s.shadowRay.dir, 1.0f));
  }
  return s.result;
}

VKPT_END_NAMESPACE

#endif

// The path-tracing estimator, one source for both renderers.
//
// Unidirectional path tracing (Kajiya 1986; pbrt-v4's PathIntegrator) with multiple
// importance sampling (Veach 1997, ch. 9): at every vertex one light sample
// (lights.h) and one BSDF sample (bsdf.h), each weighted by the power heuristic
// against the other's density, so emission found by a BSDF-sampled ray is counted at
// every vertex with its weight. Delta lights (point, spot, directional) are reached by
// light sampling alone. Russian roulette on the throughput; at most maxDepth bounces.
//
// Transmission: a light beyond a transmissive surface is sampled through it (the shadow
// ray leaves from the far side) where the shadow ray travels through no medium: beyond a
// thin wall, or out of a volume. Into a volume (KHR_materials_volume) it would cross the
// medium unattenuated, so there a direction through the surface finds emission by BSDF
// sampling alone, with weight 1. Inside a volume the path carries no medium stack: a ray
// that hits the back face of a volume's boundary travelled inside that volume and is
// attenuated by Beer–Lambert over its length (nested volumes are not told apart).
//
// Each side supplies scene access before including this file (backend_contract.h lists
// it), so that traversal stays separate (the CPU walks the BVH with an ordered stack, the
// shader stackless).
//
// Seams: a few functions of the estimator, each marked "A seam" (the MIS weights,
// roulette and the hero wavelength's draw below, GgxReflectionPdf in microfacet.h, the
// punctual falloffs and the emitter's cosine and texture in lights.h), that a test build may replace to prove its
// tests reject a wrong estimator. Such a build defines VKPT_ESTIMATOR_OVERRIDES and puts
// its estimator_overrides.h on the include path; that header defines a replaced
// function's name as a macro naming its replacement, so the default here is left out.
// Product builds define no override.
#ifndef VKPT_PATH_H
#define VKPT_PATH_H
#ifdef VKPT_ESTIMATOR_OVERRIDES
#include "estimator_overrides.h"  // first: before any header whose seams it replaces
#endif
#include "prelude.h"  // first, as in every shared header

#include "backend_contract.h"  // the backend's scene access is complete by now
#include "bsdf.h"
#include "dispersion.h"
#include "estimator.h"
#include "intersect.h"
#include "layout.h"
#include "lights.h"
#include "path_state.h"
#include "ray_cone.h"
#include "rng.h"
#include "sampling.h"
#include "shading_frame.h"

// A shader may define VKPT_VOLUMES as a specialization constant that is false when no
// triangle's material bounds a volume, so that lavapipe compiles no Beer–Lambert
// attenuation (an exp per hit) for such scenes.
#ifndef VKPT_VOLUMES
#define VKPT_VOLUMES true
#endif

VKPT_BEGIN_NAMESPACE

// MIS weights of the two strategies: Veach's power heuristic for a light sample (density
// lightPdf, which BSDF sampling would have found with bsdfPdf) and for a BSDF sample
// (bsdfPdf, which light sampling would have found with lightPdf). The two weights of one
// direction sum to 1, so the estimator stays unbiased. A seam.
#ifndef LightSampleWeight
VKPT_FN float LightSampleWeight(float lightPdf, float bsdfPdf) { return PowerHeuristic(lightPdf, bsdfPdf); }
#endif

#ifndef BsdfSampleWeight
VKPT_FN float BsdfSampleWeight(float bsdfPdf, float lightPdf) { return PowerHeuristic(bsdfPdf, lightPdf); }
#endif

// Emission seen along s.ray at the surface `sh`, `dist` away, weighted against light
// sampling: a camera ray (bsdfPdf 0) sees it whole, as does a BSDF-sampled ray that hit
// an emitter missing from the light table.
VKPT_FN vec3 WeightedEmission(VKPT_SCENE_PARAM FrameParams params, PathState s, SurfaceHit sh, float dist) {
  if (!sh.emits) return vec3(0.0f);
  float weight = 1.0f;
  if (s.bsdfPdf > 0.0f && sh.light != kInvalidIndex) {
    Light l = VKPT_LIGHT(sh.light);
    float pmf = LightChoicePmf(VKPT_SCENE_ARG params, sh.light, l, s.lightPoint, s.lightNormal);
    float lightPdf = TriangleLightPdf(l, pmf, dist, abs(dot(sh.ng, s.ray.dir)));
    weight = BsdfSampleWeight(s.bsdfPdf, lightPdf);
  }
  return weight * sh.material.emission;
}

// Radiance from the environment along s.ray, which left the scene: the map (weighted
// against light sampling unless a camera ray sees it), or the constant background.
VKPT_FN vec3 EscapedRadiance(VKPT_SCENE_PARAM FrameParams params, PathState s) {
  vec3 L = EnvRadiance(VKPT_SCENE_ARG params, s.ray.dir);
  if (SceneHasLightType(kLightEnvironment) && s.bsdfPdf > 0.0f && params.envLight != kInvalidIndex) {
    float lightPdf = VKPT_LIGHT(params.envLight).pmf * EnvironmentPdf(VKPT_SCENE_ARG params, s.ray.dir);
    L *= BsdfSampleWeight(s.bsdfPdf, lightPdf);
  }
  return L;
}

// Whether light sampling may look through the surface (see the top of this file): a
// transmissive (or diffusely transmissive) thin wall, or a volume's boundary seen from
// inside.
VKPT_FN bool SamplesLightsThrough(SurfaceHit sh, Bsdf bsdf) {
  return Transmits(bsdf) && ((sh.material.flags & kMaterialVolume) == 0u || !sh.frontFace);
}

// Next-event estimation at the vertex: samples a light and, if it can contribute, sets
// the shadow ray (from `origin`, or its twin beyond the surface for a light sampled
// through it) and the MIS-weighted contribution it carries if unoccluded.
VKPT_FN void SampleDirectLight(VKPT_SCENE_PARAM FrameParams params, VKPT_INOUT(PathState) s, SurfaceHit sh, vec3 origin,
                               Bsdf bsdf, vec3 wo, uint bounce) {
  vec2 ul = Sample2D(params.seed, s.pixel, s.sampleIndex, LightGroup(bounce));
  LightSample ls = SampleLi(VKPT_SCENE_ARG params, sh.p, sh.ng, origin, ul);
  float side = dot(ls.wi, sh.ng);
  bool through = side < 0.0f;
  if (!(ls.pdf > 0.0f) || side == 0.0f || (through && !SamplesLightsThrough(sh, bsdf))) return;
  // The geometric side decides, as for BSDF samples (ShadeHit): a shading normal that
  // disagrees would let light leak through the surface.
  vec3 wi = WorldToFrame(sh.frame, ls.wi);
  if (wi.z == 0.0f || (wi.z < 0.0f) != through) return;
  vec3 f = EvalBsdf(bsdf, wo, wi);
  if (MaxComponent(f) <= 0.0f) return;
  float weight = ls.delta ? 1.0f : LightSampleWeight(ls.pdf, BsdfPdf(bsdf, wo, wi));
  s.result.rays += 1u;
  s.shadowPending = true;
  s.shadowRay = ls.shadowRay;
  s.shadowTMax = ls.shadowTMax;
  if (through) {
    // The same target from beyond the surface: a finite light's ray ends at tMax = 1.
    vec3 beyond = OffsetRayOrigin(sh.p, -sh.ng);
    if (ls.shadowTMax == 1.0f) s.shadowRay.dir += origin - beyond;
    s.shadowRay.origin = beyond;
  }
  s.lightContribution = s.throughput * f * ls.radiance * (abs(wi.z) * weight / ls.pdf);
}

// Whether a dispersive vertex draws the path's wavelength: the first, whose path has none
// yet (0). A seam.
#ifndef DrawsWavelength
VKPT_FN bool DrawsWavelength(float wavelength) { return wavelength == 0.0f; }
#endif

// A dispersive vertex (dispersion.h): the path's first draws its wavelength and weights
// the throughput by the wavelength's colour; each refracts by its index there. The
// emission seen at the vertex does not depend on the wavelength and is left unweighted.
VKPT_FN void Disperse(FrameParams params, VKPT_INOUT(PathState) s, VKPT_INOUT(Material) mat) {
  if (DrawsWavelength(s.wavelength)) {
    vec4 hero = SampleWavelength(Sample2D(params.seed, s.pixel, s.sampleIndex, kGroupWavelength).x);
    s.wavelength = hero.x;
    s.throughput *= vec3(hero.y, hero.z, hero.w);
  }
  mat.ior = DispersiveIor(mat.ior, mat.dispersion, s.wavelength);
}

// Whether sampled direction `wi` (bs.wi in the shading frame) is usable: reflection must
// leave on the arrival side of the geometric surface (normal `ng`) and transmission on
// the other, whatever the shading normal says, or light would leak.
VKPT_FN bool LeavesOnLobeSide(BsdfSample bs, vec3 wi, vec3 ng) {
  float side = dot(wi, ng);
  return bs.pdf > 0.0f && side != 0.0f && (side < 0.0f) == (bs.wi.z < 0.0f);
}

// The ray cone widths (of a cone `coneWidth` wide at vertex `bounce`) at which the vertex
// reads its colour textures (x) and its data textures and normal maps (y; shading_frame.h):
// 0 reads level 0. What the camera sees directly is read at level 0 — a pixel's samples
// average it, and the image converges to the unfiltered answer — and data textures
// everywhere, as a filtered roughness or normal gives other light; paths filter their
// later colour lookups by their cone (--texture-lod cones), where a texel's noise is the
// larger and light is linear in the colour. A seam.
#ifndef TextureCones
VKPT_FN vec2 TextureCones(FrameParams params, uint bounce, float coneWidth) {
  return vec2(params.textureLod != 0u && bounce > 0u ? coneWidth : 0.0f, 0.0f);
}
#endif

// A path that survives Russian roulette with probability `survive` carries its throughput
// divided by it, so that its expected contribution is what it was. A seam.
#ifndef RouletteSurvivorThroughput
VKPT_FN vec3 RouletteSurvivorThroughput(vec3 throughput, float survive) { return throughput / survive; }
#endif

// Russian roulette (GAMES101: continue with probability P, divide by P) on the throughput
// times the sampled direction's weight: survival follows the throughput, so dim paths end
// early and bright ones rarely. Returns false if the path ends here.
VKPT_FN bool Survives(FrameParams params, VKPT_INOUT(PathState) s, vec3 weight, uint bounce, float u) {
  s.throughput *= weight;
  if (bounce < params.rrDepth) return true;
  float survive = min(1.0f, MaxComponent(s.throughput));
  if (!(u < survive)) return false;
  s.throughput = RouletteSurvivorThroughput(s.throughput, survive);
  return true;
}

// The path's ray s.ray has found `hit`: adds what is seen there, samples a light (setting
// s.shadowPending and the shadow ray if the sample can contribute) and the continuation
// s.ray. Returns false if no further closest-hit ray follows (the pending shadow ray, if
// any, must still be resolved before the path's radiance is final).
VKPT_FN bool ShadeHit(VKPT_SCENE_PARAM FrameParams params, VKPT_INOUT(PathState) s, HitRecord hit) {
  uint bounce = s.bounce;
  s.bounce = bounce + 1u;
  if (hit.t < 0.0f) {
    s.result.radiance += s.throughput * EscapedRadiance(VKPT_SCENE_ARG params, s);
    return false;
  }
  float coneWidth = VKPT_TEXTURES ? ConeWidthAt(s.coneWidth, s.coneSpread, hit.t) : 0.0f;
  SurfaceHit sh = MakeSurfaceHit(VKPT_SCENE_ARG s.ray, hit, TextureCones(params, bounce, coneWidth));
  if (VKPT_VOLUMES && !sh.frontFace && (sh.material.flags & kMaterialVolume) != 0u)
    s.throughput *= exp(-sh.material.attenuation * hit.t);
  s.result.radiance += s.throughput * WeightedEmission(VKPT_SCENE_ARG params, s, sh, hit.t);
  if ((sh.material.flags & kMaterialUnlit) != 0u) {
    s.result.radiance += s.throughput * sh.material.baseColor;
    return false;
  }
  // Paths have at most maxDepth bounces: the light sample at vertex k, and the ray
  // leaving it (which may escape to the environment), make k + 1.
  if (bounce >= params.maxDepth) return false;

  if (VKPT_DISPERSION && sh.material.dispersion > 0.0f) Disperse(params, s, sh.material);
  vec3 wo = WorldToFrame(sh.frame, -s.ray.dir);
  Bsdf bsdf = PrepareBsdf(sh.material, wo, sh.frontFace, WorldToFrame(sh.frame, sh.coatNormal));
  vec3 origin = OffsetRayOrigin(sh.p, sh.ng);  // of the shadow ray and a reflected continuation
  if (VKPT_LIGHT_TYPES != 0u && params.lightCount > 0u)
    SampleDirectLight(VKPT_SCENE_ARG params, s, sh, origin, bsdf, wo, bounce);

  vec4 ur = Random4(params.seed, s.pixel, s.sampleIndex, LightGroup(bounce));
  // A Lambertian sample's weight is baseColor whatever its direction, so roulette can run
  // first and a path it ends samples no direction (the same outcome, for less work).
  if (bsdf.lambert && !Survives(params, s, bsdf.baseColor, bounce, ur.w)) return false;
  vec2 ub = Sample2D(params.seed, s.pixel, s.sampleIndex, BsdfGroup(bounce));
  BsdfSample bs = SampleBsdf(bsdf, wo, vec3(ur.x, ub.x, ub.y));
  vec3 wi = FrameToWorld(sh.frame, bs.wi);
  if (!LeavesOnLobeSide(bs, wi, sh.ng)) return false;
  bool transmitted = bs.wi.z < 0.0f;
  if (!bsdf.lambert && !Survives(params, s, bs.weight, bounce, ur.w)) return false;
  // Emission found through the surface competes with light sampling only where that
  // looks through it.
  s.bsdfPdf = transmitted && !SamplesLightsThrough(sh, bsdf) ? 0.0f : bs.pdf;
  s.ray.origin = transmitted ? OffsetRayOrigin(sh.p, -sh.ng) : origin;
  s.ray.dir = wi;
  if (VKPT_LIGHT_TREE) {
    s.lightPoint = sh.p;
    s.lightNormal = sh.ng;
  }
  if (VKPT_TEXTURES) {
    s.coneWidth = coneWidth;
    s.coneSpread =
        ScatteredSpread(s.coneSpread, coneWidth, sh.curvature, MaxComponent(bs.weight) * bs.pdf / abs(bs.wi.z));
  }
  s.result.rays += 1u;
  return true;
}

// The key of the alpha decisions (alpha.h) along the path's next ray: its shadow ray if
// `shadow`, else s.ray. 0 where no material is MASK or BLEND.
VKPT_FN uint RayAlphaKey(VKPT_SCENE_PARAM FrameParams params, PathState s, bool shadow) {
  if (!VKPT_ALPHA) return 0u;
  // ShadeHit has counted the vertex that set the shadow ray.
  uvec4 h = RandomBits4(params.seed, s.pixel, s.sampleIndex, LightGroup(shadow ? s.bounce - 1u : s.bounce));
  return shadow ? h.z : h.y;
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
    HitRecord hit =
        TraceClosest(VKPT_SCENE_ARG s.ray.origin, s.ray.dir, kInfinity, RayAlphaKey(VKPT_SCENE_ARG params, s, false));
    more = ShadeHit(VKPT_SCENE_ARG params, s, hit);
    if (s.shadowPending)
      AddLightIfVisible(s, TraceOccluded(VKPT_SCENE_ARG s.shadowRay.origin, s.shadowRay.dir, s.shadowTMax,
                                         RayAlphaKey(VKPT_SCENE_ARG params, s, true)));
  }
  return s.result;
}

VKPT_END_NAMESPACE

#endif

// Arbitrary output variables (AOVs): what a compositor or a denoiser wants to know about
// each pixel besides its radiance, estimated by one source for both renderers.
//
// Sample k of an AOV pixel starts from the same camera ray as sample k of the render
// (path.h's StartPath), so the AOVs line up with the image, sample for sample, and are
// averaged like it (a box filter of one pixel). Along that ray:
//   depth, position  of the first hit: the distance from the camera along the ray
//                    (for an orthographic camera, from its film plane) and the world
//                    point; averaged over the samples that hit something, 0 if none did
//   albedo, normal   of the first hit that is not near-specular (IsAovSpecular), found by
//                    following the camera ray through mirrors and clear glass with BSDF
//                    samples of their own random numbers (AovGroup), at most
//                    kAovSpecularBounces times: the linear base colour (textures and
//                    vertex colours applied) times the weight of the specular bounces
//                    before it, and the world-space shading normal facing the ray. A ray
//                    that leaves the scene gives the albedo of what it sees there, the
//                    environment's radiance clamped to [0, 1] (so a denoiser keeps the
//                    background's edges), and normal 0 (OIDN's "no surface"); one whose
//                    walk ends otherwise gives 0 to both
//   boxTests         BVH boxes the camera ray's traversal tested (the heat map), counted
//                    by each side's own walk (the two walks differ: host/cpu/traversal.h)
// Apart from the samples, for the id AOVs only, PixelCentreTriangle finds the scene
// triangle (Triangle::sourceIndex) that a ray through the pixel's centre hits first; the
// ids name its node, material and instance, so an id is never a blend of two objects' ids
// at an edge.
// Every sum is finite: the specular weight is that of a sampled BSDF direction, which
// path.h guards in the same way, and non-finite samples are dropped by the callers.
//
// The including side supplies the scene access of path.h, plus
//   HitRecord TraceCounted(VKPT_SCENE_PARAM vec3 origin, vec3 dir, uint alphaKey,
//                          VKPT_INOUT(uint) boxTests)
// a closest hit with an unbounded tMax that adds its box tests to boxTests.
#ifndef VKPT_AOV_H
#define VKPT_AOV_H
#include "path.h"

VKPT_BEGIN_NAMESPACE

// Specular bounces an AOV ray follows before it gives up (albedo and normal 0).
const uint kAovSpecularBounces = 8u;
// A surface is near-specular for the AOVs where its GGX α = roughness² is below this
// (roughness 0.1) and it is mostly metal or transmission: a smooth plastic shows its
// diffuse base, which is what the albedo should report.
const float kAovSpecularAlpha = 0.01f;

struct AovSample {
  vec3 albedo;
  float depth;  // 0 when the camera ray left the scene
  vec3 normal;
  uint hit;  // 1 if the camera ray hit a surface
  vec3 position;
  uint boxTests;
};

// The random numbers of the AOV walk's specular bounce k: apart from every stream of the
// radiance estimator's (rng.h: camera 0, then 1 + 2k and 2 + 2k for its vertices).
VKPT_FN uint AovGroup(uint bounce) { return 0x80000000u + bounce; }

VKPT_FN bool IsAovSpecular(Bsdf bsdf) {
  return !bsdf.lambert && bsdf.alpha < kAovSpecularAlpha && (bsdf.metallic >= 0.5f || bsdf.transmission >= 0.5f);
}

// The scene triangle a ray through the centre of pixel (px, py) hits first, with the alpha
// decisions of the pixel's sample 0; kInvalidIndex if none.
VKPT_FN uint PixelCentreTriangle(VKPT_SCENE_PARAM FrameParams params, uint px, uint py) {
  uint alphaKey = RayAlphaKey(VKPT_SCENE_ARG params, StartPath(params, px, py, 0u), false);
  Ray centre = GenerateCameraRay(params, px, py, 0.5f, 0.5f);
  HitRecord hit = TraceClosest(VKPT_SCENE_ARG centre.origin, centre.dir, kInfinity, alphaKey);
  return hit.t < 0.0f ? kInvalidIndex : VKPT_TRIANGLE(hit.triangle).sourceIndex;
}

VKPT_FN AovSample TraceAovSample(VKPT_SCENE_PARAM FrameParams params, uint px, uint py, uint sampleIndex) {
  AovSample a;
  a.albedo = vec3(0.0f);
  a.depth = 0.0f;
  a.normal = vec3(0.0f);
  a.hit = 0u;
  a.position = vec3(0.0f);
  a.boxTests = 0u;
  PathState s = StartPath(params, px, py, sampleIndex);
  vec3 weight = vec3(1.0f);
  for (uint bounce = 0u; bounce <= kAovSpecularBounces; ++bounce) {
    uint alphaKey = RayAlphaKey(VKPT_SCENE_ARG params, s, false);
    HitRecord hit = bounce == 0u ? TraceCounted(VKPT_SCENE_ARG s.ray.origin, s.ray.dir, alphaKey, a.boxTests)
                                 : TraceClosest(VKPT_SCENE_ARG s.ray.origin, s.ray.dir, kInfinity, alphaKey);
    if (hit.t < 0.0f) {
      a.albedo = weight * clamp(EnvRadiance(VKPT_SCENE_ARG params, s.ray.dir), vec3(0.0f), vec3(1.0f));
      return a;
    }
    float coneWidth = VKPT_TEXTURES ? ConeWidthAt(s.coneWidth, s.coneSpread, hit.t) : 0.0f;
    SurfaceHit sh = MakeSurfaceHit(VKPT_SCENE_ARG s.ray, hit, TextureCones(params, bounce, coneWidth));
    if (bounce == 0u) {
      a.hit = 1u;
      a.depth = hit.t;  // camera rays are unit length (estimator.h)
      a.position = sh.p;
    }
    vec3 wo = WorldToFrame(sh.frame, -s.ray.dir);
    Bsdf bsdf = PrepareBsdf(sh.material, wo, sh.frontFace, WorldToFrame(sh.frame, sh.coatNormal));
    if ((sh.material.flags & kMaterialUnlit) != 0u || !IsAovSpecular(bsdf)) {
      a.albedo = weight * sh.material.baseColor;
      a.normal = sh.frame.n;
      return a;
    }
    vec4 u = Random4(params.seed, s.pixel, s.sampleIndex, AovGroup(bounce));
    BsdfSample bs = SampleBsdf(bsdf, wo, vec3(u.x, u.y, u.z));
    vec3 wi = FrameToWorld(sh.frame, bs.wi);
    if (!LeavesOnLobeSide(bs, wi, sh.ng)) return a;
    bool transmitted = bs.wi.z < 0.0f;
    weight *= bs.weight;
    s.ray.origin = OffsetRayOrigin(sh.p, transmitted ? -sh.ng : sh.ng);
    s.ray.dir = wi;
    s.bounce = bounce + 1u;
    s.coneWidth = coneWidth;
  }
  return a;
}

VKPT_END_NAMESPACE

#endif

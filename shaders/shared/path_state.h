// A path of the estimator (path.h) under construction, and its start: the camera ray of
// one sample of one pixel. Included by path.h alone, so that each compilation of the
// estimator (the CPU's three, each in its own namespace) has its own.
#ifndef VKPT_PATH_STATE_H
#define VKPT_PATH_STATE_H
#include "prelude.h"  // first, as in every shared header

#include "estimator.h"
#include "layout.h"
#include "ray_cone.h"
#include "rng.h"

VKPT_BEGIN_NAMESPACE

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
  Ray ray;  // the next closest-hit ray: camera ray, then bounce directions
  vec3 throughput;
  float bsdfPdf;      // density of s.ray's direction under the BSDF that sampled it, for MIS
                      // (0: a camera ray, or one no light sample could take: emission counts whole)
  PathSample result;  // what the path has gathered so far
  uint bounce;        // vertices found so far
  uint pixel;         // py * width + px
  uint sampleIndex;
  float coneWidth;     // the ray cone around s.ray (ray_cone.h): its width at the origin,
  float coneSpread;    // and its spread angle; in textured scenes only
  bool shadowPending;  // a light sample awaits its shadow ray
  Ray shadowRay;
  float shadowTMax;
  vec3 lightContribution;  // added to the radiance if the shadow ray is unoccluded
  float wavelength;        // nm, drawn at the first dispersive vertex (dispersion.h); 0 before
  vec3 lightPoint;         // where s.ray left from, and the geometric normal there: the shading
  vec3 lightNormal;        // point of that vertex's light choice (lights.h), for MIS; light trees only
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
  vec2 cone = CameraCone(params);
  s.coneSpread = cone.x;
  s.coneWidth = cone.y;
  s.bsdfPdf = 0.0f;
  s.result.radiance = vec3(0.0f);
  s.result.rays = 1u;  // the camera ray
  s.bounce = 0u;
  s.shadowPending = false;
  s.shadowRay = s.ray;
  s.shadowTMax = 1.0f;
  s.lightContribution = vec3(0.0f);
  s.wavelength = 0.0f;
  s.lightPoint = vec3(0.0f);
  s.lightNormal = vec3(0.0f);
  return s;
}

VKPT_END_NAMESPACE

#endif

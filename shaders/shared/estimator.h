// The pieces of the path-tracing estimator that the CPU reference (host/cpu/) and the
// compute shader must compute identically: camera rays and the next-event-estimation
// weight. Traversal is deliberately *not* shared (each side has its own), so that a
// traversal bug cannot hide in both.
#ifndef VKPT_ESTIMATOR_H
#define VKPT_ESTIMATOR_H
#include "prelude.h"
#include "layout.h"
#include "sampling.h"

VKPT_BEGIN_NAMESPACE

const float kInfinity = 3.402823466e38f;  // FLT_MAX: a ray's open tMax

struct Ray {
  vec3 origin;
  vec3 dir;
};


// Ray through pixel (px, py) at sub-pixel offset (jx, jy) ∈ [0,1)²; row 0 is the top
// of the image. A box filter of one pixel: every sample has weight 1.
VKPT_FN Ray GenerateCameraRay(FrameParams p, uint px, uint py, float jx, float jy) {
  float sx = 2.0f * (float(px) + jx) / float(p.width) - 1.0f;
  float sy = 1.0f - 2.0f * (float(py) + jy) / float(p.height);
  vec3 film = p.right * (sx * p.tanHalfFovY * p.aspect) + p.up * (sy * p.tanHalfFovY);
  Ray r;
  if (p.orthographic != 0u) {
    r.origin = p.origin + film;
    r.dir = p.forward;
  } else {
    r.origin = p.origin;
    r.dir = normalize(p.forward + film);
  }
  return r;
}

// Radiance-to-contribution factor of one light sample for next-event estimation.
// The rendering equation's integral over directions is rewritten over the emitter's area
// (dω = cos θ' dA / r², GAMES101 lecture 16), so a point x sampled with area density
// pdfA = pmf / area contributes
//     f · Le · cos θ · cos θ' / (r² · pdfA)
// where θ is at the shading point (normal n, facing the viewer) and θ' at the emitter
// (normal nl). This returns cos θ · cos θ' / (r² · pdfA), or 0 when the emitter faces
// away (one-sided emitters emit from their front face only) or the light is below the
// surface.
VKPT_FN float LightSampleWeight(vec3 p, vec3 n, vec3 x, vec3 nl, bool twoSided, float pmf, float area) {
  vec3 d = x - p;
  float dist2 = dot(d, d);
  if (!(dist2 > 0.0f)) return 0.0f;
  vec3 wi = d * inversesqrt(dist2);
  float cosSurface = dot(n, wi);
  float cosLight = -dot(nl, wi);
  if (twoSided) cosLight = abs(cosLight);
#ifdef VKPT_MUTANT_NO_LIGHT_COSINE
  // Deliberately wrong (test builds only): forgets cos θ' at the emitter.
  if (cosLight > 0.0f) cosLight = 1.0f;
#endif
  if (cosSurface <= 0.0f || cosLight <= 0.0f) return 0.0f;
  return cosSurface * cosLight * area / (dist2 * pmf);
}

VKPT_END_NAMESPACE

#endif

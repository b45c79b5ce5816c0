// The pieces of the path-tracing estimator that the CPU reference (host/cpu/) and the
// compute shader must compute identically: rays and camera rays. Traversal is
// deliberately *not* shared (each side has its own), so that a traversal bug cannot hide
// in both.
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

VKPT_END_NAMESPACE

#endif

// What the estimator knows about a surface point a ray has hit: position, geometric
// normal, the shading frame the BSDF works in, the material and whether it emits.
#ifndef VKPT_SHADING_FRAME_H
#define VKPT_SHADING_FRAME_H
#include "prelude.h"
#include "layout.h"
#include "sampling.h"
#include "estimator.h"

VKPT_BEGIN_NAMESPACE

struct SurfaceHit {
  vec3 p;
  uint light;   // the hit triangle's light-table entry, or kInvalidIndex
  vec3 ng;      // unit geometric normal, on the side the ray arrived from
  bool emits;   // the material emits towards the ray (front face, or double-sided)
  Frame frame;  // shading frame; frame.n is the shading normal
  Material material;
};

// Surfaces scatter on both sides: the geometric normal is turned to face the ray.
// One-sided materials emit from their front face only (glTF's winding).
VKPT_FN SurfaceHit MakeSurfaceHit(VKPT_SCENE_PARAM Ray ray, HitRecord hit) {
  Triangle tri = VKPT_TRIANGLE(hit.triangle);
  SurfaceHit sh;
  sh.material = VKPT_MATERIAL(tri.material);
  sh.light = tri.light;
  vec3 ng = normalize(cross(tri.e1, tri.e2));
  bool frontFace = dot(ng, ray.dir) < 0.0f;
  sh.ng = frontFace ? ng : -ng;
  sh.emits = frontFace || (sh.material.flags & kMaterialDoubleSided) != 0u;
  sh.p = tri.v0 + hit.b1 * tri.e1 + hit.b2 * tri.e2;
  sh.frame = FrameFromNormal(sh.ng);
  return sh;
}

VKPT_END_NAMESPACE

#endif

// The shared estimator (shaders/shared/path.h) instantiated for the CPU: scene access
// goes through a RenderScene, traversal through the CPU's own ordered BVH walk.
#pragma once

#include "cpu/traversal.h"
#include "render/render_scene.h"
#include "shared/estimator.h"

#define VKPT_SCENE_PARAM const ::vkpt::RenderScene &scene,
#define VKPT_SCENE_ARG scene,
#define VKPT_TRIANGLE(i) scene.triangles[i]
#define VKPT_MATERIAL(i) scene.materials[i]
#define VKPT_LIGHT(i) scene.lights[i]
#define VKPT_LIGHT_CDF(i) scene.lights[i].cdf
#define VKPT_SHADING(i) scene.shading[i]
#define VKPT_VERTEX_COLORS (!scene.vertexColors.empty())
#define VKPT_VERTEX_COLORS_OF(i) scene.vertexColors[i]
#define VKPT_ENV_TEXEL(i) scene.environment.texels[i]
#define VKPT_ENV_CDF(i) scene.environment.cdf[i]

namespace vkpt::shader {

inline HitRecord TraceClosest(const RenderScene& scene, vec3 origin, vec3 dir, float tMax) {
  return IntersectClosest(scene, origin, dir, tMax);
}

inline bool TraceOccluded(const RenderScene& scene, vec3 origin, vec3 dir, float tMax) {
  return Occluded(scene, origin, dir, tMax);
}

}  // namespace vkpt::shader

#include "shared/environment.h"
#include "shared/path.h"

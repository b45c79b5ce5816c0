// The shared estimator (shaders/shared/path.h) instantiated for the CPU: scene access
// goes through a RenderScene, traversal through the CPU's own ordered BVH walk.
#pragma once

#include "cpu/traversal.h"
#include "render/render_scene.h"
#include "render/scene_access.h"
#include "shared/estimator.h"

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

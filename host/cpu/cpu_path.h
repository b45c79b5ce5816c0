// The shared estimator (shaders/shared/path.h) instantiated for the CPU: scene access
// goes through a RenderScene, traversal through the CPU's own ordered BVH walk.
#pragma once

#include "cpu/path_tracer.h"
#include "cpu/traversal.h"
#include "render/render_scene.h"
#include "render/scene_access.h"
#include "shared/estimator.h"

namespace vkpt::shader {

// Scenes without MASK or BLEND materials take the walk that tests no alpha.
inline HitRecord TraceClosest(const internal::RenderScene& scene, vec3 origin, vec3 dir, float tMax, uint alphaKey) {
  return scene.alphaTested ? IntersectClosestAlpha(scene, origin, dir, tMax, alphaKey)
                           : IntersectClosest(scene, origin, dir, tMax);
}

inline bool TraceOccluded(const internal::RenderScene& scene, vec3 origin, vec3 dir, float tMax, uint alphaKey) {
  return scene.alphaTested ? OccludedAlpha(scene, origin, dir, tMax, alphaKey) : Occluded(scene, origin, dir, tMax);
}

}  // namespace vkpt::shader

namespace vkpt::internal {

// The radiance of a path (a PathSample of one of the estimator's compilations), its rays
// counted in `stats`.
template <class PathSample>
glm::vec3 CountRays(const PathSample& s, SampleStats& stats) {
  stats.rays += s.rays;
  return s.radiance;
}

}  // namespace vkpt::internal

#include "shared/environment.h"
#include "shared/path.h"

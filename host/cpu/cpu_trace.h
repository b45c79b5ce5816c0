// What the shared estimator (shaders/shared/path.h) calls on the CPU: scene access
// through a RenderScene, traversal through the CPU's own ordered BVH walk. Every
// compilation of the estimator includes this first; cpu/cpu_path.h then compiles the
// general one, and simple_path.cpp, core_path.cpp and the tests' variants their own in
// their own namespaces.
#pragma once

#include "cpu/light_importances_sse2.h"
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

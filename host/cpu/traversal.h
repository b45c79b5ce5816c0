// Closest-hit and any-hit queries for the CPU reference tracer: an ordered, stack-based
// walk over the wide layout (bvh/wide_layout.h), a node's eight child boxes tested at
// once (one AVX2 step where the CPU has AVX2, else two 4-wide ones) and the nearest child
// entered first. Both forms give the same bits. Independent of the skip-link walk the shader uses,
// so one traversal bug cannot hide in both renderers.
#pragma once

#include "render/render_scene.h"
#include "shared/layout.h"

namespace vkpt::internal {

// The hit record the GPU returns too (shaders/shared/layout.h): t < 0 means no hit.
using Hit = shader::HitRecord;

// Every triangle opaque: the geometry alone.
Hit IntersectClosest(const RenderScene& scene, glm::vec3 origin, glm::vec3 dir, float tMax);

// True if anything is hit with t in (0, tMax). `dir` need not be unit length.
bool Occluded(const RenderScene& scene, glm::vec3 origin, glm::vec3 dir, float tMax);

// The same, passing through the hits that alpha (shaders/shared/alpha.h) leaves out for
// the ray with key `alphaKey`.
Hit IntersectClosestAlpha(const RenderScene& scene, glm::vec3 origin, glm::vec3 dir, float tMax, uint32_t alphaKey);
bool OccludedAlpha(const RenderScene& scene, glm::vec3 origin, glm::vec3 dir, float tMax, uint32_t alphaKey);

// The closest hit with an open tMax, alpha tested where the scene has MASK or BLEND
// materials, adding the boxes the walk tested (kBvhWidth per wide node) to `boxTests`: the
// heat map AOV (shaders/shared/aov.h).
Hit IntersectClosestCounted(const RenderScene& scene, glm::vec3 origin, glm::vec3 dir, uint32_t alphaKey,
                            uint32_t& boxTests);

// The walk's instruction set: AVX2 where the CPU has it (chosen once, at the first
// query), else the portable one. Tests name one to compare them.
enum class WalkIsa { kPortable, kAvx2 };
bool WalkIsaSupported(WalkIsa isa);
WalkIsa BestWalkIsa();
Hit IntersectClosest(WalkIsa isa, const RenderScene& scene, glm::vec3 origin, glm::vec3 dir, float tMax);
bool Occluded(WalkIsa isa, const RenderScene& scene, glm::vec3 origin, glm::vec3 dir, float tMax);

}  // namespace vkpt::internal

#include "cpu/traversal.h"

#include <cstring>
#include <vector>

#include "render/scene_access.h"
#include "shared/alpha.h"
#include "shared/estimator.h"
#include "shared/intersect.h"
#include "util/float4.h"

// The AVX2 walk needs GCC's per-function target pragma (and x86).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#include <immintrin.h>
#define VKPT_AVX2_WALK 1
#else
#define VKPT_AVX2_WALK 0
#endif

namespace vkpt::internal {
namespace {

namespace portable {
#define VKPT_WALK_AVX2 0
#include "cpu/wide_walk.h"
#undef VKPT_WALK_AVX2
}  // namespace portable

#if VKPT_AVX2_WALK
#pragma GCC push_options
#pragma GCC target("avx2")
namespace avx2 {
#define VKPT_WALK_AVX2 1
#include "cpu/wide_walk.h"
#undef VKPT_WALK_AVX2
}  // namespace avx2
#pragma GCC pop_options
#endif

// One walk's queries.
struct Queries {
  Hit (*closest)(const RenderScene&, glm::vec3, glm::vec3, float);
  bool (*occluded)(const RenderScene&, glm::vec3, glm::vec3, float);
  Hit (*closestAlpha)(const RenderScene&, glm::vec3, glm::vec3, float, uint32_t);
  bool (*occludedAlpha)(const RenderScene&, glm::vec3, glm::vec3, float, uint32_t);
  Hit (*counted)(const RenderScene&, glm::vec3, glm::vec3, uint32_t, uint32_t&);
};

template <class W>
constexpr Queries QueriesOf() {
  return {&W::IntersectClosest, &W::Occluded, &W::IntersectClosestAlpha, &W::OccludedAlpha,
          &W::IntersectClosestCounted};
}

const Queries& QueriesFor(WalkIsa isa) {
  static constexpr Queries kPortable = QueriesOf<portable::Walk>();
#if VKPT_AVX2_WALK
  static constexpr Queries kAvx2 = QueriesOf<avx2::Walk>();
  if (isa == WalkIsa::kAvx2) return kAvx2;
#endif
  return kPortable;
}

// The walk of this CPU, chosen once.
const Queries& Best() {
  static const Queries& queries = QueriesFor(BestWalkIsa());
  return queries;
}

}  // namespace

bool WalkIsaSupported(WalkIsa isa) {
#if VKPT_AVX2_WALK
  if (isa == WalkIsa::kAvx2) return __builtin_cpu_supports("avx2");
#endif
  return isa == WalkIsa::kPortable;
}

WalkIsa BestWalkIsa() { return WalkIsaSupported(WalkIsa::kAvx2) ? WalkIsa::kAvx2 : WalkIsa::kPortable; }

Hit IntersectClosest(WalkIsa isa, const RenderScene& scene, glm::vec3 origin, glm::vec3 dir, float tMax) {
  return QueriesFor(isa).closest(scene, origin, dir, tMax);
}

bool Occluded(WalkIsa isa, const RenderScene& scene, glm::vec3 origin, glm::vec3 dir, float tMax) {
  return QueriesFor(isa).occluded(scene, origin, dir, tMax);
}

Hit IntersectClosest(const RenderScene& scene, glm::vec3 origin, glm::vec3 dir, float tMax) {
  return Best().closest(scene, origin, dir, tMax);
}

bool Occluded(const RenderScene& scene, glm::vec3 origin, glm::vec3 dir, float tMax) {
  return Best().occluded(scene, origin, dir, tMax);
}

Hit IntersectClosestAlpha(const RenderScene& scene, glm::vec3 origin, glm::vec3 dir, float tMax, uint32_t alphaKey) {
  return Best().closestAlpha(scene, origin, dir, tMax, alphaKey);
}

bool OccludedAlpha(const RenderScene& scene, glm::vec3 origin, glm::vec3 dir, float tMax, uint32_t alphaKey) {
  return Best().occludedAlpha(scene, origin, dir, tMax, alphaKey);
}

Hit IntersectClosestCounted(const RenderScene& scene, glm::vec3 origin, glm::vec3 dir, uint32_t alphaKey,
                            uint32_t& boxTests) {
  return Best().counted(scene, origin, dir, alphaKey, boxTests);
}

}  // namespace vkpt::internal

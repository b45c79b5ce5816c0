// The shared AOV estimator (shaders/shared/aov.h) instantiated for the CPU: the scene
// access of cpu_path.h, and the camera ray's box tests from the counting walk.
#include "cpu/aov_tracer.h"

#include <atomic>
#include <cmath>

#include "cpu/cpu_path.h"
#include "util/parallel.h"

namespace vkpt::shader {

inline HitRecord TraceCounted(const internal::RenderScene& scene, vec3 origin, vec3 dir, uint alphaKey,
                              uint& boxTests) {
  return IntersectClosestCounted(scene, origin, dir, alphaKey, boxTests);
}

}  // namespace vkpt::shader

#include "shared/aov.h"

namespace vkpt::internal {
namespace {

bool IsFinite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

AovSums RenderAovsCpu(const internal::RenderScene& scene, const shader::FrameParams& params, const AovRequest& request,
                      unsigned threads) {
  const uint32_t samples = request.samples;
  AovSums sums;
  sums.width = params.width;
  sums.height = params.height;
  sums.samples = samples;
  sums.pixels.resize(size_t(params.width) * params.height);
  std::atomic<uint64_t> nonFinite{0};
  ParallelFor(params.height, ThreadCount(threads), [&](size_t y) {
    uint64_t dropped = 0;
    for (uint32_t x = 0; x < params.width; ++x) {
      AovPixelSums& p = sums.pixels[y * params.width + x];
      if (request.ids) p.triangle = shader::PixelCentreTriangle(scene, params, x, uint32_t(y));
      for (uint32_t s = 0; s < samples; ++s) {
        const shader::AovSample a = shader::TraceAovSample(scene, params, x, uint32_t(y), s);
        if (!IsFinite(a.albedo) || !IsFinite(a.normal) || !IsFinite(a.position) || !std::isfinite(a.depth)) {
          ++dropped;
          continue;
        }
        p.albedo += glm::dvec3(a.albedo);
        p.normal += glm::dvec3(a.normal);
        p.boxTests += a.boxTests;
        if (a.hit == 0u) continue;
        p.position += glm::dvec3(a.position);
        p.depth += a.depth;
        ++p.hits;
      }
    }
    nonFinite.fetch_add(dropped);
  });
  sums.nonFinite = nonFinite.load();
  return sums;
}

}  // namespace vkpt::internal

// The CPU reference renderer: runs the shared estimator (shaders/shared/path.h) over
// all pixels, a row at a time on util/parallel.h's threads.
#include "cpu/path_tracer.h"

#include <atomic>
#include <chrono>
#include <cmath>

#include "cpu/cpu_path.h"
#include "util/error.h"
#include "util/parallel.h"

namespace vkpt {

using namespace shader;

glm::vec3 SampleRadiance(const RenderScene& scene, const FrameParams& params, uint32_t px, uint32_t py,
                         uint32_t sampleIndex, SampleStats& stats) {
  PathSample s = TracePath(scene, params, px, py, sampleIndex);
  stats.rays += s.rays;
  return s.radiance;
}

CpuRenderResult RenderCpu(const RenderScene& scene, const FrameParams& params, const CpuRenderOptions& options) {
  if (scene.pairLayout.pairs.empty() && scene.pairLayout.packets.empty())
    throw Error("the CPU renderer needs a RenderScene prepared with forCpu = true");
  CpuRenderResult result;
  result.image = Image(params.width, params.height);
  result.image.variance.assign(result.image.pixels.size(), glm::vec3(0.0f));
  const unsigned threads = std::min<unsigned>(ThreadCount(options.threads), params.height);
  result.threads = threads;

  // Counted per row and added up once per row: per sample, the shared counters would
  // bounce their cache line between cores.
  std::atomic<uint64_t> rays{0}, nonFinite{0};
  auto renderRow = [&](size_t y) {
    SampleStats st;
    for (uint32_t x = 0; x < params.width; ++x) {
      glm::dvec3 sum(0.0), sumSq(0.0);
      for (uint32_t s = 0; s < params.sampleCount; ++s) {
        glm::vec3 L = SampleRadiance(scene, params, x, uint32_t(y), params.sampleBegin + s, st);
        if (!std::isfinite(L.x) || !std::isfinite(L.y) || !std::isfinite(L.z)) {
          ++st.nonFinite;
          continue;
        }
        sum += glm::dvec3(L);
        sumSq += glm::dvec3(L) * glm::dvec3(L);
      }
      const double n = params.sampleCount;
      glm::dvec3 mean = sum / n;
      size_t i = y * params.width + x;
      result.image.pixels[i] = glm::vec3(mean);
      // Unbiased sample variance divided by n: the variance of the pixel mean.
      if (n > 1) result.image.variance[i] = glm::vec3(glm::max(sumSq / n - mean * mean, 0.0) / (n - 1.0));
    }
    rays.fetch_add(st.rays);
    nonFinite.fetch_add(st.nonFinite);
  };

  auto t0 = std::chrono::steady_clock::now();
  if (options.progress) ParallelForWithProgress(params.height, threads, renderRow, options.progress);
  else ParallelFor(params.height, threads, renderRow);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  result.stats = {rays.load(), nonFinite.load()};
  return result;
}

}  // namespace vkpt

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

namespace {

// Pixel (x, y)'s samples, summed in sample order (so the sums are the same for any
// thread count); non-finite samples are counted and left out.
template <bool kSimple>
PixelSums SamplePixel(const RenderScene& scene, const FrameParams& params, uint32_t x, uint32_t y, SampleStats& stats) {
  PixelSums sums;
  for (uint32_t s = 0; s < params.sampleCount; ++s) {
    glm::vec3 L = kSimple ? SampleRadianceSimple(scene, params, x, y, params.sampleBegin + s, stats)
                          : SampleRadiance(scene, params, x, y, params.sampleBegin + s, stats);
    if (!std::isfinite(L.x) || !std::isfinite(L.y) || !std::isfinite(L.z)) {
      ++stats.nonFinite;
      continue;
    }
    sums.sum += glm::dvec3(L);
    sums.sumOfSquares += glm::dvec3(L) * glm::dvec3(L);
  }
  return sums;
}

}  // namespace

RenderResult RenderCpu(const RenderScene& scene, const FrameParams& params, const CpuRenderOptions& options) {
  if (scene.pairLayout.pairs.empty() && scene.pairLayout.packets.empty())
    throw Error("the CPU renderer needs a RenderScene prepared with forCpu = true");
  Film film(params.width, params.height, params.sampleCount);
  const unsigned threads = std::min<unsigned>(ThreadCount(options.threads), params.height);

  // Counted per row and added up once per row: per sample, the shared counters would
  // bounce their cache line between cores.
  std::atomic<uint64_t> rays{0}, nonFinite{0};
  const bool simple = IsSimpleScene(scene, params);
  auto renderRow = [&](size_t y) {
    SampleStats st;
    for (uint32_t x = 0; x < params.width; ++x)
      film.SetPixel(y * params.width + x, simple ? SamplePixel<true>(scene, params, x, uint32_t(y), st)
                                                 : SamplePixel<false>(scene, params, x, uint32_t(y), st));
    rays.fetch_add(st.rays);
    nonFinite.fetch_add(st.nonFinite);
  };

  auto t0 = std::chrono::steady_clock::now();
  if (options.progress) ParallelForWithProgress(params.height, threads, renderRow, options.progress);
  else ParallelFor(params.height, threads, renderRow);
  RenderResult result;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  result.image = film.TakeImage();
  result.rays = rays.load();
  result.nonFinite = nonFinite.load();
  result.threads = threads;
  result.engine = "cpu (" + std::to_string(threads) + " threads)";
  return result;
}

}  // namespace vkpt

// The CPU reference renderer: runs the shared estimator (shaders/shared/path.h) over
// all pixels on a pool of threads.
#include "cpu/path_tracer.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include "cpu/cpu_path.h"
#include "util/error.h"

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
  unsigned threads = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  threads = std::min<unsigned>(threads, params.height);
  result.threads = threads;

  std::atomic<uint32_t> nextRow{0}, rowsDone{0};
  std::vector<SampleStats> perThread(threads);
  auto worker = [&](unsigned id) {
    // Counted locally: the threads' entries of perThread share a cache line, and
    // updating them per sample would bounce it between cores.
    SampleStats st;
    for (uint32_t y; (y = nextRow.fetch_add(1)) < params.height;) {
      for (uint32_t x = 0; x < params.width; ++x) {
        glm::dvec3 sum(0.0), sumSq(0.0);
        for (uint32_t s = 0; s < params.sampleCount; ++s) {
          glm::vec3 L = SampleRadiance(scene, params, x, y, params.sampleBegin + s, st);
          if (!std::isfinite(L.x) || !std::isfinite(L.y) || !std::isfinite(L.z)) {
            ++st.nonFinite;
            continue;
          }
          sum += glm::dvec3(L);
          sumSq += glm::dvec3(L) * glm::dvec3(L);
        }
        const double n = params.sampleCount;
        glm::dvec3 mean = sum / n;
        size_t i = size_t(y) * params.width + x;
        result.image.pixels[i] = glm::vec3(mean);
        // Unbiased sample variance divided by n: the variance of the pixel mean.
        if (n > 1) result.image.variance[i] = glm::vec3(glm::max(sumSq / n - mean * mean, 0.0) / (n - 1.0));
      }
      rowsDone.fetch_add(1);
    }
    perThread[id] = st;
  };

  auto t0 = std::chrono::steady_clock::now();
  std::vector<std::thread> pool;
  for (unsigned i = 1; i < threads; ++i) pool.emplace_back(worker, i);
  if (options.progress) {
    // The calling thread reports progress and then joins the work.
    std::thread w0(worker, 0u);
    while (rowsDone.load() < params.height) {
      options.progress(double(rowsDone.load()) / params.height);
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    w0.join();
    options.progress(1.0);
  } else {
    worker(0);
  }
  for (auto& t : pool) t.join();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const SampleStats& st : perThread) {
    result.stats.rays += st.rays;
    result.stats.nonFinite += st.nonFinite;
  }
  return result;
}

}  // namespace vkpt

// The CPU reference renderer: runs the shared estimator (shaders/shared/path.h) over
// all pixels, a row at a time on util/parallel.h's threads.
#include "cpu/path_tracer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>

#include "cpu/aov_tracer.h"
#include "cpu/cpu_path.h"
#include "util/error.h"
#include "util/parallel.h"

namespace vkpt::internal {

using namespace shader;

glm::vec3 SampleRadiance(const RenderScene& scene, const FrameParams& params, uint32_t px, uint32_t py,
                         uint32_t sampleIndex, SampleStats& stats) {
  return CountRays(TracePath(scene, params, px, py, sampleIndex), stats);
}

namespace {

// Pixel (x, y)'s samples [begin, begin + count), added to `sums` in sample order (so the
// sums are the same for any thread count); non-finite samples are counted and left out.
using Estimator = glm::vec3 (*)(const RenderScene&, const FrameParams&, uint32_t, uint32_t, uint32_t, SampleStats&);

// The estimator compiled for the least the scene needs: the simple one, the one without
// the layered extensions, or the general one. Each gives the same bits.
Estimator ChooseEstimator(const RenderScene& scene, const FrameParams& params) {
  if (IsSimpleScene(scene, params)) return SampleRadianceSimple;
  return IsCoreScene(scene) ? SampleRadianceCore : SampleRadiance;
}

template <Estimator kEstimator>
void SamplePixel(const RenderScene& scene, const FrameParams& params, uint32_t x, uint32_t y, uint32_t begin,
                 uint32_t count, PixelSums& sums, SampleStats& stats) {
  for (uint32_t s = 0; s < count; ++s) {
    glm::vec3 L = kEstimator(scene, params, x, y, begin + s, stats);
    ++sums.samples;
    if (!std::isfinite(L.x) || !std::isfinite(L.y) || !std::isfinite(L.z)) {
      ++stats.nonFinite;
      continue;
    }
    sums.sum += glm::dvec3(L);
    sums.sumOfSquares += glm::dvec3(L) * glm::dvec3(L);
  }
}

class CpuFrame final : public FrameRenderer {
 public:
  CpuFrame(const RenderScene& scene, const FrameParams& params, unsigned threads)
      : scene_(scene),
        params_(params),
        threads_(std::min<unsigned>(ThreadCount(threads), params.height)),
        estimator_(ChooseEstimator(scene, params)) {
    if (scene.wideLayout.nodes.empty() && scene.wideLayout.packets.empty())
      throw Error("the CPU renderer needs a RenderScene prepared with forCpu = true");
    sums_.width = params.width;
    sums_.height = params.height;
    sums_.pixels.resize(size_t(params.width) * params.height);
  }

  void AddSamples(uint32_t begin, uint32_t count, std::span<const uint8_t> active,
                  const std::function<void(double)>& progress) override {
    // Counted per row and added up once per row: per sample, the shared counters would
    // bounce their cache line between cores.
    std::atomic<uint64_t> rays{0}, nonFinite{0};
    auto renderRow = [&](size_t y) {
      SampleStats st;
      for (uint32_t x = 0; x < params_.width; ++x) {
        const size_t i = y * params_.width + x;
        if (!active.empty() && !active[i]) continue;
        if (estimator_ == SampleRadianceSimple)
          SamplePixel<SampleRadianceSimple>(scene_, params_, x, uint32_t(y), begin, count, sums_.pixels[i], st);
        else if (estimator_ == SampleRadianceCore)
          SamplePixel<SampleRadianceCore>(scene_, params_, x, uint32_t(y), begin, count, sums_.pixels[i], st);
        else SamplePixel<SampleRadiance>(scene_, params_, x, uint32_t(y), begin, count, sums_.pixels[i], st);
      }
      rays.fetch_add(st.rays);
      nonFinite.fetch_add(st.nonFinite);
    };
    if (progress) ParallelForWithProgress(params_.height, threads_, renderRow, progress);
    else ParallelFor(params_.height, threads_, renderRow);
    sums_.rays += rays.load();
    sums_.nonFinite += nonFinite.load();
  }

  void AddSumsTo(FrameSums& into) override { AddChunk(into, sums_); }
  void Clear() override {
    sums_.pixels.assign(sums_.pixels.size(), PixelSums{});
    sums_.rays = sums_.nonFinite = sums_.cutShort = 0;
  }
  AovSums RenderAovs(const AovRequest& request) override { return RenderAovsCpu(scene_, params_, request, threads_); }
  std::string Engine() const override { return "cpu (" + std::to_string(threads_) + " threads)"; }
  unsigned Threads() const { return threads_; }

 private:
  const RenderScene& scene_;
  const FrameParams params_;
  const unsigned threads_;
  const Estimator estimator_;
  FrameSums sums_;
};

}  // namespace

std::unique_ptr<FrameRenderer> BeginCpuFrame(const RenderScene& scene, const FrameParams& params, unsigned threads) {
  return std::make_unique<CpuFrame>(scene, params, threads);
}

RenderResult RenderCpu(const RenderScene& scene, const FrameParams& params, const CpuRenderOptions& options) {
  CpuFrame frame(scene, params, options.threads);
  auto t0 = std::chrono::steady_clock::now();
  frame.AddSamples(params.sampleBegin, params.sampleCount, {}, options.progress);
  RenderResult result;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const FrameSums sums = frame.Sums();
  result.image = ResolveFilm(sums);
  result.rays = sums.rays;
  result.nonFinite = sums.nonFinite;
  result.threads = frame.Threads();
  result.engine = frame.Engine();
  return result;
}

}  // namespace vkpt::internal

#include "quality.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cpu/path_tracer.h"
#include "gltf/gltf_loader.h"
#include "image/image.h"
#include "procedural.h"
#include "render/light_table.h"
#include "render/render_scene.h"
#include "report.h"
#include "shared/estimator.h"
#include "util/error.h"
#include "vk/vk_renderer.h"

namespace vkpt::internal::bench {
namespace {

// relMSE = mean over pixels and channels of (a − r)² / (r² + 0.01).
double RelMse(const std::vector<glm::dvec3>& sum, double spp, const Image& ref) {
  double total = 0.0;
  for (size_t i = 0; i < ref.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      double a = sum[i][c] / spp, r = ref.pixels[i][c];
      total += (a - r) * (a - r) / (r * r + 0.01);
    }
  return total / (3.0 * double(ref.pixels.size()));
}

// "What users feel" (the benchmark issue): seconds of rendering until an image's relMSE
// against a converged reference first drops to a target. Renders progressively (chunks
// growing by ~6 %, so the time overshoots the true crossing by at most that much) until
// relMSE ≤ target or the time budget is spent. `render` renders samples
// [begin, begin + count) and returns (image of their mean, seconds).
using ChunkRenderer = std::function<std::pair<Image, double>(uint32_t begin, uint32_t count)>;
struct TimeToQuality {
  std::optional<double> seconds;  // nullopt: not reached
  uint32_t spp = 0;
};
TimeToQuality SecondsToQuality(const Image& ref, double target, const ChunkRenderer& render, const std::string& name) {
  std::vector<glm::dvec3> sum(ref.pixels.size(), glm::dvec3(0.0));
  double seconds = 0.0;
  uint32_t spp = 0;
  while (seconds < 300.0 && spp < (1u << 16)) {
    uint32_t chunk = std::max(1u, spp / 16);
    auto [img, s] = render(spp, chunk);
    seconds += s;
    for (size_t i = 0; i < sum.size(); ++i) sum[i] += glm::dvec3(img.pixels[i]) * double(chunk);
    spp += chunk;
    double e = RelMse(sum, spp, ref);
    if (e <= target) {
      std::fprintf(stderr, "  %s: relMSE %.3g at %u spp after %.2f s\n", name.c_str(), e, spp, seconds);
      return {seconds, spp};
    }
  }
  std::fprintf(stderr, "  %s: relMSE target not reached in %.0f s (%u spp)\n", name.c_str(), seconds, spp);
  return {std::nullopt, spp};
}

// relMSE times render seconds, estimated from kRelMseRenders independent renders of
// kRelMseSpp samples per pixel (disjoint sample ranges): the expected relMSE of an
// unbiased render falls as 1/time, so this product is the relMSE of one second's render,
// and two estimators' products compare them at equal time. The mean of the renders'
// relMSE, not a time to a threshold, whose first crossing comes early for the noisier
// estimator. relMSE includes the reference's own error (tiny against one such render's).
constexpr uint32_t kRelMseRenders = 8, kRelMseSpp = 32;
struct RelMseTime {
  double product = 0.0;     // mean relMSE × mean seconds per render
  double relativeSe = 0.0;  // the product's standard error over it (the relMSE's spread)
};
RelMseTime RelMseTimesSeconds(const Image& ref, const ChunkRenderer& render) {
  double sum = 0.0, sumSq = 0.0, seconds = 0.0;
  for (uint32_t k = 0; k < kRelMseRenders; ++k) {
    auto [img, s] = render(k * kRelMseSpp, kRelMseSpp);
    std::vector<glm::dvec3> one(ref.pixels.size());
    for (size_t i = 0; i < one.size(); ++i) one[i] = glm::dvec3(img.pixels[i]);
    const double e = RelMse(one, 1.0, ref);
    sum += e;
    sumSq += e * e;
    seconds += s;
  }
  const double n = kRelMseRenders, mean = sum / n;
  const double se = std::sqrt(std::max(0.0, sumSq / n - mean * mean) / (n - 1.0));
  return {mean * seconds / n, se / mean};
}

// One light sampler's prepared scene, by the name it has in keys and lines.
struct SamplerScene {
  std::string name;  // "power" or "tree"
  const RenderScene* rs;
};

// The light tree's figures against the power choice's, for each backend measured.
void SetTreeRatios(Report& rep) {
  for (const std::string b : {"cpu", "gpu"}) {
    std::optional<double> p = rep.Get(b + "_power_seconds_to_quality"), t = rep.Get(b + "_tree_seconds_to_quality");
    rep.Set(b + "_tree_vs_power", p && t ? std::optional<double>(*t / *p) : std::nullopt);
    // relMSE at equal time, the power choice's over the tree's, and its standard error.
    std::optional<double> pe = rep.Get(b + "_power_relmse_seconds"), te = rep.Get(b + "_tree_relmse_seconds");
    if (!pe || !te) continue;
    const double gain = *pe / *te;
    rep.Set(b + "_tree_equal_time_gain", gain);
    rep.Set(b + "_tree_equal_time_gain_se", gain * std::hypot(*rep.Get(b + "_power_relmse_seconds_rel_se"),
                                                              *rep.Get(b + "_tree_relmse_seconds_rel_se")));
  }
}

// The time-to-quality figures as lines.
void PrintQuality(const Report& rep, const std::vector<SamplerScene>& samplers, double target, unsigned threads) {
  std::printf("vkpt-bench: seconds to relMSE <= %.1e, %u threads, device %s\n", target, threads, rep.device.c_str());
  for (const std::string backend : {"cpu", "gpu"}) {
    for (const SamplerScene& s : samplers) {
      const std::string key = backend + "_" + s.name;
      const std::optional<double> v = rep.Get(key + "_seconds_to_quality"), n = rep.Get(key + "_spp_to_quality");
      const std::string line = std::string(backend == "cpu" ? "CPU" : "GPU") + ", " +
                               (s.name == "power" ? "power-proportional lights" : "light tree");
      if (v) std::printf("  %-32s %8.2f s (%0.f spp)", line.c_str(), *v, n.value_or(0));
      else std::printf("  %-32s %8s", line.c_str(), "not reached");
      const std::optional<double> ratio = rep.Get(backend + "_tree_vs_power");
      if (s.name == "tree" && ratio) std::printf("   %.2fx the power choice's time", *ratio);
      std::printf("\n");
    }
    const std::optional<double> gain = rep.Get(backend + "_tree_equal_time_gain");
    if (gain)
      std::printf(
          "  %s relMSE at equal time: the power choice's is %.2fx the tree's (+-%.2g; means of %u renders of "
          "%u spp)\n",
          backend == "cpu" ? "CPU" : "GPU", *gain, *rep.Get(backend + "_tree_equal_time_gain_se"), kRelMseRenders,
          kRelMseSpp);
  }
}

}  // namespace

// Seconds to quality on each backend, for each light sampler the scene can use: the
// power-proportional choice and, where it has at least two emissive triangles, point or
// spot lights, the light tree (render/light_tree.h), whose time is also given as a ratio
// to the power choice's, measured in the same run: relMSE falls as 1/time, so the ratio
// is also that of their relMSE at equal time.
int Quality(const Options& o, unsigned threads) {
  Image ref = ReadPfm(o.quality);
  Scene scene = o.procedural ? ProceduralScene(o.procedural) : LoadGltf(o.scene);
  const BvhBuildOptions bvhOptions = BuildOptions(o, threads);
  RenderScene power = PrepareRenderScene(scene, bvhOptions);
  RenderScene tree = power;
  ChooseLightSampler(tree, LightSampler::kTree);
  std::vector<SamplerScene> samplers = {{"power", &power}};
  if (tree.treeLights > 0) samplers.push_back({"tree", &tree});
  const Camera cam = scene.cameras.empty() ? DefaultCamera(scene.bounds) : scene.cameras[0];
  Report rep;
  rep.threads = threads;
  std::fprintf(stderr, "vkpt-bench: time to relMSE <= %.1e against %s (%ux%u)\n", o.target, o.quality.c_str(),
               ref.width, ref.height);
  // Times one backend: `render` renders a frame of the scene it was made for.
  auto measure = [&](const std::string& key, const RenderScene& rs,
                     const std::function<RenderResult(const shader::FrameParams&)>& render) {
    shader::FrameParams p = MakeFrameParams(rs, cam, ref.width, ref.height);
    p.seed = 1;  // the reference should use another seed
    p.maxDepth = 32;
    p.rrDepth = 3;
    if (rs.lights.empty()) p.background = glm::vec3(1.0f);
    const ChunkRenderer chunks = [&](uint32_t begin, uint32_t count) {
      shader::FrameParams q = p;
      q.sampleBegin = begin;
      q.sampleCount = count;
      RenderResult r = render(q);
      return std::make_pair(std::move(r.image), r.seconds);
    };
    const TimeToQuality t = SecondsToQuality(ref, o.target, chunks, key);
    rep.Set(key + "_seconds_to_quality", t.seconds);
    rep.Set(key + "_spp_to_quality", double(t.spp));
    if (samplers.size() < 2) return;
    const RelMseTime r = RelMseTimesSeconds(ref, chunks);
    rep.Set(key + "_relmse_seconds", r.product);
    rep.Set(key + "_relmse_seconds_rel_se", r.relativeSe);
  };
  for (const SamplerScene& s : samplers) {
    CpuRenderOptions opt;
    opt.threads = threads;
    measure("cpu_" + s.name, *s.rs, [&](const shader::FrameParams& q) { return RenderCpu(*s.rs, q, opt); });
  }
  try {
    vk::Context ctx(vk::ContextOptions{});
    rep.device = ctx.DeviceName();
    for (const SamplerScene& s : samplers) {
      vk::GpuRenderer gpu(ctx, *s.rs);
      measure("gpu_" + s.name, *s.rs, [&](const shader::FrameParams& q) { return gpu.Render(q); });
    }
  } catch (const Error& e) {
    std::fprintf(stderr, "vkpt-bench: GPU figures skipped: %s\n", e.what());
    rep.device = "none";
  }
  if (samplers.size() > 1) SetTreeRatios(rep);
  if (o.json) PrintJson(rep);
  else PrintQuality(rep, samplers, o.target, threads);
  return 0;
}

}  // namespace vkpt::internal::bench

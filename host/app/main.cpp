// vkpt: command-line front end. Data flows one way:
//   glTF file → Scene (host/scene) → BVH + RenderScene (host/bvh, host/render)
//   → renderer (host/cpu or host/vk) → Image (host/image) → file.
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "app/environment_option.h"
#include "app/options.h"
#include "app/render_loop.h"
#include "app/run_stats.h"
#include "cpu/path_tracer.h"
#include "dist/chunk_dealer.h"
#include "dist/cluster.h"
#include "image/aov.h"
#include "image/chunked_frame.h"
#include "image/denoise.h"
#include "image/image.h"
#include "image/image_compare.h"
#include "image/noise_estimate.h"
#include "render/light_table.h"
#include "render/render_scene.h"
#include "scene/gltf_loader.h"
#include "shared/sampling.h"
#include "util/atomic_write.h"
#include "util/byte_size.h"
#include "util/error.h"
#include "util/graceful_stop.h"
#include "vk/context.h"
#include "vk/vk_denoise.h"
#include "vk/vk_renderer.h"

namespace vkpt {
namespace {

using shader::MaxComponent;

// " alpha MASK (cutoff c)", " alpha BLEND", or nothing for OPAQUE; with the factor's alpha.
std::string AlphaNote(const Material& m) {
  char note[64] = "";
  if (m.flags & shader::kMaterialAlphaMask)
    std::snprintf(note, sizeof note, " alpha MASK %.3g (cutoff %.3g)", m.alpha, m.alphaCutoff);
  else if (m.flags & shader::kMaterialAlphaBlend) std::snprintf(note, sizeof note, " alpha BLEND %.3g", m.alpha);
  return note;
}

void PrintLoadReport(const Scene& scene, const RenderScene& rs, const Camera& cam, uint32_t camIndex) {
  std::printf("scene: %s\n", scene.path.c_str());
  std::printf("  triangles: %zu, materials: %zu (incl. default), lights: %zu\n", scene.triangles.size(),
              scene.materials.size(), rs.lights.size());
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    std::printf(
        "  material %zu \"%s\": baseColor (%.4g, %.4g, %.4g) metallic %.3g roughness %.3g specular %.3g ior %.3g "
        "transmission %.3g%s emission (%.6g, %.6g, %.6g)%s%s%s\n",
        i, scene.materialNames[i].c_str(), m.baseColor.x, m.baseColor.y, m.baseColor.z, m.metallic, m.roughness,
        m.specular, m.ior, m.transmission, (m.flags & shader::kMaterialVolume) ? " (volume)" : "", m.emission.x,
        m.emission.y, m.emission.z, (m.flags & shader::kMaterialDoubleSided) ? " double-sided" : "",
        (m.flags & shader::kMaterialUnlit) ? " unlit" : "", AlphaNote(m).c_str());
  }
  if (!scene.colors.empty()) std::printf("  vertex colours (COLOR_0): multiply the base colour\n");
  if (!scene.textures.empty()) {
    uint64_t texels = 0;
    for (const TextureImage& im : scene.images) texels += uint64_t(im.width) * im.height;
    std::printf("  textures: %zu from %zu images, %llu texels at level 0\n", scene.textures.size(), scene.images.size(),
                (unsigned long long)texels);
  }
  if (scene.generatedTangentPrimitives > 0)
    std::printf("  tangents: generated (MikkTSpace) for %u normal-mapped primitive(s) without TANGENT\n",
                scene.generatedTangentPrimitives);
  std::printf("  bounds: (%.6g, %.6g, %.6g) .. (%.6g, %.6g, %.6g)\n", scene.bounds.lo.x, scene.bounds.lo.y,
              scene.bounds.lo.z, scene.bounds.hi.x, scene.bounds.hi.y, scene.bounds.hi.z);
  char which[16] = "default";
  if (!scene.cameras.empty()) std::snprintf(which, sizeof which, "#%u", camIndex);
  std::printf("  cameras: %zu; using %s \"%s\" at (%.6g, %.6g, %.6g) looking (%.4g, %.4g, %.4g), %s %.4g\n",
              scene.cameras.size(), which, cam.name.c_str(), cam.position.x, cam.position.y, cam.position.z,
              cam.forward.x, cam.forward.y, cam.forward.z,
              cam.orthographic ? "orthographic ymag" : "perspective yfov(deg)",
              cam.orthographic ? cam.ymag : cam.yfov * 180.0 / M_PI);
  std::printf("  memory: %s counted for the scene, of --max-memory %s\n", FormatBytes(scene.memoryCounted).c_str(),
              FormatBytes(scene.memoryLimit).c_str());
  for (const std::string& w : scene.warnings) std::printf("  warning: %s\n", w.c_str());
  for (const std::string& f : scene.ignoredFeatures) std::printf("  ignored: %s\n", f.c_str());
}

std::function<void(double)> ProgressLine() {
  if (!isatty(STDERR_FILENO)) return {};
  return [](double f) { std::fprintf(stderr, "\rrendering: %5.1f%%", 100.0 * f); };
}

void EndProgressLine() {
  if (isatty(STDERR_FILENO)) std::fprintf(stderr, "\r%*s\r", 20, "");
}

RenderResult RenderOnCpu(const RenderScene& rs, const shader::FrameParams& params, const Options& o) {
  CpuRenderOptions cpu;
  cpu.threads = o.threads;
  cpu.progress = ProgressLine();
  RenderResult r = RenderCpu(rs, params, cpu);
  EndProgressLine();
  return r;
}

double SecondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The budgets of the options.
RenderBudget BudgetFromOptions(const Options& o) {
  RenderBudget b;
  b.maxSpp = o.spp;
  b.seconds = o.time;
  b.noiseTarget = o.noiseTarget;
  b.adaptive = o.Adaptive();
  if (o.noiseTarget) b.adaptiveThreshold = *o.noiseTarget;
  b.checkpointSeconds = o.checkpoint;
  b.chunkSpp = o.chunkSpp;
  return b;
}

// A render and what came with it.
struct FrameOutcome {
  ProgressiveRender render;
  AovSums aovs;                // --aov: the AOV pass's sums (empty without one)
  double uploadSeconds = 0.0;  // the scene into device memory and the pipeline compiled
  double aovSeconds = 0.0;
  std::vector<RankShare> ranks;  // an MPI job's ranks (empty for one process)
};

// This process's renderer of the frame: on the Vulkan device if there is one, else on the
// CPU. `gpu` keeps the device's scene alive with it.
struct BackendFrame {
  std::unique_ptr<vk::GpuRenderer> gpu;
  std::unique_ptr<FrameRenderer> frame;
  double uploadSeconds = 0.0;
};

BackendFrame BeginBackendFrame(vk::Context* ctx, const RenderScene& rs, const shader::FrameParams& params,
                               const Options& o) {
  BackendFrame b;
  const auto t0 = std::chrono::steady_clock::now();
  if (ctx) {
    b.gpu = std::make_unique<vk::GpuRenderer>(*ctx, rs);
    vk::GpuRenderOptions options;
    options.batch = o.batch;
    b.frame = b.gpu->BeginFrame(params, options);
    b.uploadSeconds = SecondsSince(t0);
  } else {
    b.frame = BeginCpuFrame(rs, params, o.threads);
  }
  return b;
}

// Writes the image of `sums` to --out during the render.
void WriteCheckpoint(const Options& o, const FrameSums& sums, uint32_t spp) {
  WriteImage(ResolveFilm(sums), o.out, o.exposure);
  if (o.verbose) std::printf("  checkpoint: %s at %u spp\n", o.out.c_str(), spp);
  std::fflush(stdout);
}

// The AOV pass, if some --aov (or --denoise) needs it.
void RenderAovPass(FrameRenderer& frame, const Options& o, FrameOutcome& out) {
  if (!o.denoise && std::none_of(o.aovs.begin(), o.aovs.end(), NeedsAovPass)) return;
  const auto t0 = std::chrono::steady_clock::now();
  out.aovs = frame.RenderAovs(std::min(kAovSamples, out.render.spp));
  out.aovSeconds = SecondsSince(t0);
}

// The render under the options' budgets, in chunks (image/chunked_frame.h), then the AOV
// pass. The image is written at every checkpoint.
FrameOutcome RenderFrame(vk::Context* ctx, const RenderScene& rs, const shader::FrameParams& params, const Options& o) {
  FrameOutcome out;
  BackendFrame backend = BeginBackendFrame(ctx, rs, params, o);
  out.uploadSeconds = backend.uploadSeconds;
  ChunkedFrame frame(std::move(backend.frame), o.chunkSpp);
  RenderLoopHooks hooks;
  hooks.progress = ProgressLine();
  hooks.checkpoint = [&o](const FrameSums& sums, uint32_t spp) { WriteCheckpoint(o, sums, spp); };
  // Flushed line by line: a script reading a pipe sees each pass as it ends.
  if (o.verbose)
    hooks.passReport = [](const std::string& line) {
      std::printf("  %s\n", line.c_str());
      std::fflush(stdout);
    };
  out.render = RenderProgressively(frame, BudgetFromOptions(o), hooks);
  EndProgressLine();
  RenderAovPass(frame, o, out);
  return out;
}

// A whole number from the environment, or `otherwise`.
long EnvironmentNumber(const char* name, long otherwise) {
  const char* v = std::getenv(name);
  return v && *v ? std::strtol(v, nullptr, 10) : otherwise;
}

// A chunk of the frame on this rank's backend: its sums alone. For the tests of an MPI
// job (docs/testing.md), VKPT_TEST_CHUNK_DELAY_MS slows this rank down by that much per
// chunk, and VKPT_TEST_FAIL_AFTER_CHUNKS=N makes it fail after N chunks of its own.
ChunkRenderer ChunkRendererOf(FrameRenderer& frame, const ChunkPlan& plan) {
  const long delayMs = EnvironmentNumber("VKPT_TEST_CHUNK_DELAY_MS", 0);
  const long failAfter = EnvironmentNumber("VKPT_TEST_FAIL_AFTER_CHUNKS", -1);
  auto rendered = std::make_shared<long>(0);
  return [&frame, plan, delayMs, failAfter, rendered](uint32_t chunk, std::span<const uint8_t> active) {
    if ((*rendered)++ == failAfter)
      throw Error("failing at chunk " + std::to_string(chunk) + " (VKPT_TEST_FAIL_AFTER_CHUNKS)");
    if (delayMs > 0) std::this_thread::sleep_for(std::chrono::milliseconds(delayMs));
    frame.Clear();
    frame.AddSamples(plan.Begin(chunk), plan.Samples(chunk), active, {});
    return frame.Sums();
  };
}

// RenderFrame on rank 0 of an MPI job: the chunks dealt among the ranks (dist/chunk_dealer.h)
// until --spp, --time, --noise-target, converged pixels or a signal ends the dealing,
// with the adaptive decisions of RenderProgressively, then the AOV pass here.
FrameOutcome RenderFrameOnCluster(Cluster& cluster, FrameRenderer& frame, const Options& o) {
  FrameOutcome out;
  const ChunkPlan plan{o.spp, o.chunkSpp};
  const RenderBudget budget = BudgetFromOptions(o);
  const auto t0 = std::chrono::steady_clock::now();
  DealerHooks hooks;
  std::optional<Decision> last;  // of the last decision point
  if (budget.Decisions()) {
    hooks.decisions.nextPoint = [&o](uint32_t spp) { return NextDecisionPoint(spp, o.chunkSpp); };
    hooks.decisions.decide = [&](const FrameSums& sums, uint32_t spp, std::vector<uint8_t>& active) {
      last = Decide(budget, sums, active);
      if (o.verbose) std::printf("  decision at %u spp%s\n", spp, last->report.c_str());
      return last->stop.has_value();
    };
  }
  if (std::function<void(double)> line = ProgressLine())
    hooks.progress = [&, line](double chunks) {
      line(FinishedFraction(budget, chunks * o.spp, SecondsSince(t0), last ? last->noise : INFINITY));
    };
  hooks.stopDealing = [&] { return GracefulStop::Signal() != 0 || (o.time && SecondsSince(t0) >= *o.time); };
  hooks.checkpoint = [&o](const FrameSums& sums, uint32_t spp) { WriteCheckpoint(o, sums, spp); };
  hooks.checkpointSeconds = o.checkpoint;
  DealtFrame dealt = DealChunks(cluster, plan, ChunkRendererOf(frame, plan), hooks);
  EndProgressLine();
  ProgressiveRender& r = out.render;
  r.seconds = SecondsSince(t0);
  r.sums = std::move(dealt.sums);
  r.spp = dealt.spp;
  for (uint32_t c = 0; c < dealt.chunks; ++c) r.sppPerPass.push_back(plan.Samples(c));
  r.samples = TotalSamples(r.sums);
  r.stoppedBy = dealt.decidedToStop             ? *last->stop
                : dealt.chunks == plan.Chunks() ? StopReason::kSpp
                : GracefulStop::Signal()        ? StopReason::kSignal
                                                : StopReason::kTime;
  r.signal = GracefulStop::Signal();
  r.estimatedRelMse = EstimatedRelMse(r.sums);
  r.activePixels = last ? last->activePixels : r.sums.pixels.size();
  r.engine = "mpi: " + std::to_string(cluster.Size()) + " ranks, rank 0 " + frame.Engine();
  out.ranks = std::move(dealt.ranks);
  RenderAovPass(frame, o, out);
  return out;
}

// A finished render as the reports read it.
RenderResult ResultOf(const ProgressiveRender& p) {
  RenderResult r;
  r.image = ResolveFilm(p.sums);
  r.rays = p.sums.rays;
  r.nonFinite = p.sums.nonFinite;
  r.cutShort = p.sums.cutShort;
  r.seconds = p.seconds;
  r.engine = p.engine;
  return r;
}

int ListDevices() {
  std::vector<vk::DeviceInfo> devices = vk::ListDevices();
  if (devices.empty()) {
    std::printf("no Vulkan devices (install mesa-vulkan-drivers for lavapipe, a software device)\n");
    return 0;
  }
  for (const vk::DeviceInfo& d : devices)
    std::printf("%u: %s (%s, Vulkan %u.%u)%s\n", d.index, d.name.c_str(), d.TypeName(), VK_API_VERSION_MAJOR(d.apiVersion),
                VK_API_VERSION_MINOR(d.apiVersion), d.hasComputeQueue ? "" : " [no compute queue]");
  return 0;
}

// The Vulkan context for --backend vulkan (errors are fatal) or auto (no device: the
// CPU renders, after saying why).
std::unique_ptr<vk::Context> OpenVulkan(const Options& o) {
  if (o.backend == Backend::Cpu && !o.compare) return nullptr;
  // lavapipe reads LP_NUM_THREADS when the device is created: --threads applies to it too.
  if (o.threads) setenv("LP_NUM_THREADS", std::to_string(o.threads).c_str(), 1);
  vk::ContextOptions opt;
  opt.validation = o.validation;
  opt.device = o.device;
  if (o.backend == Backend::Vulkan || o.compare || !o.device.empty() || o.validation)
    return std::make_unique<vk::Context>(opt);
  try {
    return std::make_unique<vk::Context>(opt);
  } catch (const Error& e) {
    std::fprintf(stderr, "vkpt: %s\nvkpt: rendering on the CPU instead\n", e.what());
    return nullptr;
  }
}

std::string DiffPath(const std::string& out) {
  size_t dot = out.find_last_of('.');
  return out.substr(0, dot) + "-diff.png";
}

// --diff A B: two existing images, no rendering.
int Diff(const Options& o) {
  Image a = ReadPfm(o.diff[0]);
  Image b = ReadPfm(o.diff[1]);
  if (!o.outGiven.empty()) CheckOutputPath(o.outGiven);
  ImageComparison c = CompareImages(a, b);
  std::printf("vkpt: %s (A) vs %s (B)\n%s\n", o.diff[0].c_str(), o.diff[1].c_str(), c.Summary().c_str());
  if (!o.outGiven.empty()) WriteImage(DifferenceHeatmap(a, b), o.outGiven);
  return c.statisticallyAgree ? 0 : 4;
}

// The camera --camera names (the scene's first, or a default one framing the scene if
// it has none); its index goes to *index.
Camera ChooseCamera(const Scene& scene, const Options& o, uint32_t* index) {
  *index = o.camera.value_or(0);
  if (scene.cameras.empty()) {
    if (o.camera) throw Error(o.scene + ": --camera " + std::to_string(*o.camera) + " given, but the scene has no cameras");
    return DefaultCamera(scene.bounds);
  }
  if (*index >= scene.cameras.size())
    throw Error(o.scene + ": --camera " + std::to_string(*index) + " is out of range; the scene has " +
                std::to_string(scene.cameras.size()) + " camera(s)");
  return scene.cameras[*index];
}

// Resolution: what the user said; the missing side follows the camera's aspect ratio.
glm::uvec2 ImageSize(const Camera& cam, const Options& o) {
  float aspect = cam.aspectRatio > 0.0f ? cam.aspectRatio : 1.0f;
  uint32_t width = o.width.value_or(o.height ? uint32_t(std::lround(*o.height * aspect)) : 512u);
  uint32_t height = o.height.value_or(uint32_t(std::lround(width / aspect)));
  return {std::max(1u, std::min(width, 16384u)), std::max(1u, std::min(height, 16384u))};
}

// The BVH and the renderers' arrays, with the environment map. `gpu`: a Vulkan device will
// render, so the shader's direction-ordered copies of the tree are built; the CPU's layout
// only where the CPU renders (no device, or --compare).
RenderScene PrepareForRender(const Scene& scene, const Options& o, bool gpu, EnvironmentMap env) {
  BvhBuildOptions bvhOptions;
  bvhOptions.maxLeafSize = o.leafSize;
  bvhOptions.splits = o.splits;
  bvhOptions.threads = o.threads;
  bvhOptions.directionCopies = gpu;
  RenderScene rs = PrepareRenderScene(scene, bvhOptions, !gpu || o.compare);
  rs.environment = std::move(env);
  if (rs.environment.width > 0) AddEnvironmentLight(rs, o.envIntensity);
  return rs;
}

// The frame constants from the options; a scene without light sources (HasLightSources)
// is lit by a white environment unless --env or --background says otherwise (and is warned about if that is
// black).
shader::FrameParams FrameFromOptions(const RenderScene& rs, const Camera& cam, glm::uvec2 size, const Options& o,
                                     bool report) {
  shader::FrameParams params = MakeFrameParams(rs, cam, size.x, size.y);
  params.seed = o.seed;
  params.sampleBegin = 0;
  params.sampleCount = o.spp;
  params.maxDepth = o.maxDepth;
  params.rrDepth = o.rrDepth;
  params.textureLod = o.textureLod ? 1u : 0u;
  if (!o.env.empty()) {
    SetEnvironmentParams(params, rs.environment, o.envRotation, o.envIntensity);
  } else if (o.background) {
    params.background = glm::vec3((*o.background)[0], (*o.background)[1], (*o.background)[2]);
  } else if (!HasLightSources(rs)) {
    params.background = glm::vec3(1.0f);
    if (report && o.verbose)
      std::printf("  no lights%s: lit by a white environment (see --background)\n",
                  rs.lights.empty() ? "" : " but emissive textures");
  }
  if (report && rs.lights.empty() && o.env.empty() && MaxComponent(params.background) <= 0.0f)
    std::fprintf(stderr, "vkpt: warning: %s: no lights and a black background; the image will be black\n",
                 o.scene.c_str());
  return params;
}

// --compare: the CPU reference (A) against the Vulkan render (B), with a heat map beside
// the output. Same seed, same estimator: the backends must agree pixel by pixel
// (lockstep) and in every region's mean (statistics); 4 if they do not, else 0.
int CompareBackends(const RenderResult& reference, const RenderResult& r, const Options& o) {
  ImageComparison c = CompareImages(reference.image, r.image);
  WriteImage(DifferenceHeatmap(reference.image, r.image), DiffPath(o.out));
  std::printf("vkpt: --compare: A = %s (%.3f s), B = %s (%.3f s), seed %u\n%s\n  heat map: %s\n",
              reference.engine.c_str(), reference.seconds, r.engine.c_str(), r.seconds, o.seed, c.Summary().c_str(),
              DiffPath(o.out).c_str());
  if (c.lockstepAgree && c.statisticallyAgree) return 0;
  std::fprintf(stderr, "vkpt: --compare: the CPU and Vulkan images DISAGREE\n");
  return 4;
}

// The summary after a render: samples and why they stopped, rates, the image's mean, the
// scene and its BVH, warnings.
void PrintRenderReport(const Scene& scene, const RenderScene& rs, const RenderResult& r, const ProgressiveRender& p,
                       const Options& o) {
  const uint32_t width = r.image.width, height = r.image.height;
  const double samples = double(p.samples);
  glm::dvec3 mean(0.0);
  for (const glm::vec3& px : r.image.pixels) mean += glm::dvec3(px);
  mean /= double(r.image.pixels.size());
  std::printf("vkpt: %s -> %s: %ux%u, %u spp, %s\n", o.scene.c_str(), o.out.c_str(), width, height, p.spp,
              r.engine.c_str());
  char why[96];
  switch (p.stoppedBy) {
    case StopReason::kTime: std::snprintf(why, sizeof why, "--time %g s", *o.time); break;
    case StopReason::kNoiseTarget: std::snprintf(why, sizeof why, "--noise-target %g", *o.noiseTarget); break;
    case StopReason::kConverged: std::snprintf(why, sizeof why, "every pixel converged (--adaptive)"); break;
    case StopReason::kSignal: std::snprintf(why, sizeof why, "%s", p.signal == SIGTERM ? "SIGTERM" : "SIGINT"); break;
    default: std::snprintf(why, sizeof why, "--spp %u", o.spp); break;
  }
  std::printf("  stopped by %s after %zu pass(es); estimated relMSE %.4g", why, p.sppPerPass.size(), p.estimatedRelMse);
  if (o.Adaptive())
    std::printf("; adaptive: %.2f spp per pixel on average, %llu pixels still active", samples / r.image.pixels.size(),
                (unsigned long long)p.activePixels);
  std::printf("\n  time %.3f s, %.3f Msamples/s, %.3f Mrays/s, mean radiance (%.6g, %.6g, %.6g)\n", r.seconds,
              samples / r.seconds * 1e-6, double(r.rays) / r.seconds * 1e-6, mean.x, mean.y, mean.z);
  const BvhStats& bvh = rs.bvhStats;
  const char* kind = bvh.spatialSplits ? "spatial" : "object";
  char choice[96] = "";
  if (bvh.rejectedSahCost > 0.0)
    std::snprintf(choice, sizeof choice, " (auto: %s splits' SAH cost was %.3f)", bvh.spatialSplits ? "object" : "spatial",
                  bvh.rejectedSahCost);
  std::printf(
      "  scene: %zu triangles (%u degenerate skipped), %zu emissive; BVH: %s splits%s, %u nodes, %u leaves, "
      "depth %u, %u triangle references, SAH cost %.3f, built in %.2f ms\n",
      scene.triangles.size(), rs.degenerateTriangles, rs.lights.size(), kind, choice, bvh.nodes, bvh.leaves, bvh.depth,
      bvh.references, bvh.sahCost, bvh.buildMs);
  if (!rs.textures.empty())
    std::printf("  textures: %zu, %s with their mip levels\n", rs.textures.size(),
                FormatBytes(rs.texels.size() * sizeof(uint32_t)).c_str());
  if (r.nonFinite)
    std::printf("  warning: %llu non-finite samples were discarded\n", (unsigned long long)r.nonFinite);
  if (r.cutShort)
    std::fprintf(stderr,
                 "vkpt: warning: %llu samples came near lavapipe's limit of 65535 loop iterations per SIMD group "
                 "and may have been cut short (image biased dark); use --backend cpu or a smaller --max-depth\n",
                 (unsigned long long)r.cutShort);
}

// Everything the render needs, from the options: the scene, its device and arrays.
struct Prepared {
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  RunTimes times;
  Scene scene;
  std::unique_ptr<vk::Context> ctx;
  RenderScene rs;
  shader::FrameParams params;
};

Prepared Prepare(const Options& o, bool report) {
  Prepared p;
  CheckOutputPath(o.out);  // fail before a long render, not after
  if (!o.stats.empty()) CheckWritablePath(o.stats, "a stats");
  auto phase = std::chrono::steady_clock::now();
  auto lap = [&phase](double& seconds) {
    seconds = SecondsSince(phase);
    phase = std::chrono::steady_clock::now();
  };
  p.scene = LoadGltf(o.scene, o.load);
  lap(p.times.load);
  EnvironmentMap env = LoadEnvironment(o, p.scene);
  lap(p.times.environment);
  uint32_t camIndex = 0;
  const Camera cam = ChooseCamera(p.scene, o, &camIndex);
  const glm::uvec2 size = ImageSize(cam, o);
  // The device before the scene's arrays: without one (auto backend) the CPU renders, and
  // only then does the scene need the CPU's BVH layout.
  p.ctx = OpenVulkan(o);
  phase = std::chrono::steady_clock::now();
  p.rs = PrepareForRender(p.scene, o, p.ctx != nullptr, std::move(env));
  lap(p.times.prepare);
  if (report && o.verbose) PrintLoadReport(p.scene, p.rs, cam, camIndex);
  p.params = FrameFromOptions(p.rs, cam, size, o, report);
  return p;
}

// After the render: denoising, the files, the reports and the stats; the exit status.
int Finish(const Options& o, Prepared& p, const FrameOutcome& frame, const RenderResult* reference) {
  const ProgressiveRender& progressive = frame.render;
  const RenderResult r = ResultOf(progressive);
  RunTimes& times = p.times;
  times.upload = frame.uploadSeconds;
  times.render = r.seconds;
  times.aov = frame.aovSeconds;
  const uint32_t validationMessages = p.ctx ? p.ctx->ValidationMessages() : 0;

  auto phase = std::chrono::steady_clock::now();
  auto lap = [&phase](double& seconds) {
    seconds = SecondsSince(phase);
    phase = std::chrono::steady_clock::now();
  };
  std::optional<Image> denoised;
  if (o.denoise) {
    const DenoiseInput input = PrepareDenoise(r.image, frame.aovs);
    denoised = FinishDenoise(input, p.ctx ? vk::AtrousGpu(*p.ctx, input) : AtrousCpu(input, o.threads));
    lap(times.denoise);
  }
  std::vector<std::string> files = WriteImageWithAovs(
      denoised ? *denoised : r.image, ResolveAovs(o.aovs, frame.aovs, progressive.sums, r.image), o.out, o.exposure);
  if (denoised) {
    files.push_back(SiblingPath(o.out, "raw"));
    WriteImage(r.image, files.back(), o.exposure);
  }
  lap(times.write);
  int status = reference ? CompareBackends(*reference, r, o) : 0;
  PrintRenderReport(p.scene, p.rs, r, progressive, o);
  for (const RankShare& rank : frame.ranks)
    std::printf("  %s: %u chunk(s) in %.3f s, %s sent\n", rank.name.c_str(), rank.chunks, rank.renderSeconds,
                FormatBytes(rank.bytesSent).c_str());
  if (!o.aovs.empty()) {
    std::string names, written;
    for (Aov aov : o.aovs) names += std::string(names.empty() ? "" : ", ") + AovName(aov);
    for (size_t k = 1; k < files.size(); ++k) written += std::string(written.empty() ? "" : ", ") + files[k];
    if (written.empty()) written = o.out;
    std::printf("  AOVs: %s (%u samples per pixel, %.3f s) in %s\n", names.c_str(), frame.aovs.samples, times.aov,
                written.c_str());
  }
  if (denoised)
    std::printf("  denoised (à-trous, %s) in %.3f s; the raw image is %s\n", p.ctx ? "vulkan" : "cpu", times.denoise,
                SiblingPath(o.out, "raw").c_str());
  if (validationMessages) {
    std::fprintf(stderr, "vkpt: %u Vulkan validation message(s) were reported\n", validationMessages);
    status = 3;
  }
  if (const int sig = GracefulStop::Signal()) {
    std::fprintf(stderr, "vkpt: interrupted by %s: %s holds the %u spp rendered (%s)\n",
                 sig == SIGTERM ? "SIGTERM" : "SIGINT", o.out.c_str(), progressive.spp,
                 progressive.stoppedBy == StopReason::kSignal ? "stopped early" : "the render had finished");
    status = 128 + sig;
  }
  if (!o.stats.empty()) {
    times.total = SecondsSince(p.start);
    const std::string json = StatsJson(o, {p.scene, p.rs, r, progressive, reference, times, validationMessages, status,
                                           frame.aovs.samples, files, frame.ranks});
    WriteFileAtomically(o.stats, {reinterpret_cast<const uint8_t*>(json.data()), json.size()});
  }
  return status;
}

int Run(const Options& o) {
  if (o.listDevices) return ListDevices();
  if (!o.diff.empty()) return Diff(o);
  Prepared p = Prepare(o, true);
  std::optional<RenderResult> reference;
  if (o.compare) reference = RenderOnCpu(p.rs, p.params, o);
  // From here the first SIGINT/SIGTERM stops the render after its pass, and the image of
  // the samples taken is still written.
  GracefulStop stop;
  const FrameOutcome frame = RenderFrame(p.ctx.get(), p.rs, p.params, o);
  return Finish(o, p, frame, reference ? &*reference : nullptr);
}

// Every error is one line of at most a few hundred characters, whatever a file or an
// argument put into it.
void PrintError(const char* kind, std::string what) {
  std::replace(what.begin(), what.end(), '\n', ' ');
  constexpr size_t kMaxLength = 480;
  if (what.size() > kMaxLength) what = what.substr(0, kMaxLength - 80) + " … " + what.substr(what.size() - 60);
  std::fprintf(stderr, "vkpt: %s: %s\n", kind, what.c_str());
}

// Runs `step` and returns its exit status (0, or 1 and the error's message).
int Attempt(const std::function<void()>& step, std::string* message) {
  try {
    step();
    return 0;
  } catch (const Error& e) {
    *message = e.what();
  } catch (const std::bad_alloc&) {
    *message = "out of memory";
  } catch (const std::exception& e) {
    *message = e.what();
  }
  return 1;
}

// A step every rank takes (parsing, loading): every rank's outcome, gathered. When some
// failed, rank 0 prints each different message once (naming the ranks when they differ
// between ranks) and every rank returns the worst status.
int AgreeOnOutcome(Cluster& cluster, int status, const std::string& message, const char* kind) {
  const std::vector<std::string> all = cluster.Gather(std::to_string(status) + ":" + message);
  const int worst = cluster.MaxOf(status);
  if (worst == 0 || cluster.Rank() != 0) return worst;
  std::vector<std::pair<std::string, std::vector<int>>> distinct;  // message, its ranks
  for (int r = 0; r < int(all.size()); ++r) {
    if (all[r].rfind("0:", 0) == 0) continue;
    const std::string text = all[r].substr(all[r].find(':') + 1);
    auto it = std::find_if(distinct.begin(), distinct.end(), [&](const auto& d) { return d.first == text; });
    if (it == distinct.end()) distinct.push_back({text, {r}});
    else it->second.push_back(r);
  }
  for (const auto& [text, ranks] : distinct) {
    if (ranks.size() == all.size()) {
      PrintError(kind, text);
    } else {
      for (int r : ranks) PrintError(kind, cluster.Name(r) + ": " + text);
    }
  }
  return worst;
}

// The options that must be the same on every rank: all but where and how each renders.
uint64_t FrameKey(const Options& o, const Prepared& p) {
  Options shared = o;
  shared.backend = Backend::Auto;
  shared.device.clear();
  shared.threads = 0;
  shared.batch = 0;
  shared.validation = shared.verbose = false;
  const std::string key = OptionsAsJson(shared) + std::to_string(p.scene.contentHash);
  uint64_t h = 1469598103934665603ull;  // FNV-1a
  for (unsigned char c : key) h = (h ^ c) * 1099511628211ull;
  return h;
}

// One rank of an MPI job: every rank loads the scene and builds its arrays; rank 0 deals
// the chunks and writes the files, the others render what it deals them.
int RunRank(Cluster& cluster, int argc, char** argv) {
  Options o;
  std::string message;
  int status = 0;
  try {
    o = ParseOptions(argc, argv);
    if (o.compare) throw UsageError("--compare renders in one process; run it without mpirun");
    if (!o.diff.empty() || o.listDevices || o.help || o.version)
      throw UsageError("--diff, --list-devices, --help and --version run in one process; run them without mpirun");
  } catch (const UsageError& e) {
    status = 2;
    message = e.what();
  }
  if ((status = AgreeOnOutcome(cluster, status, message, "usage error"))) return status;
  Prepared p;
  BackendFrame backend;
  status = Attempt(
      [&] {
        p = Prepare(o, cluster.Rank() == 0);
        backend = BeginBackendFrame(p.ctx.get(), p.rs, p.params, o);
      },
      &message);
  if ((status = AgreeOnOutcome(cluster, status, message, "error"))) return status;
  if (!cluster.AllEqual(FrameKey(o, p))) {
    if (cluster.Rank() == 0)
      PrintError("usage error",
                 "the ranks were given different frames: only --backend, --device, --threads, --batch, "
                 "--validation and -v may differ between ranks");
    return 2;
  }
  GracefulStop stop;  // rank 0 stops dealing at a signal; the others finish their chunk
  if (cluster.Rank() != 0) {
    RenderDealtChunks(cluster, ChunkRendererOf(*backend.frame, ChunkPlan{o.spp, o.chunkSpp}));
    return 0;
  }
  FrameOutcome frame = RenderFrameOnCluster(cluster, *backend.frame, o);
  frame.uploadSeconds = backend.uploadSeconds;
  return Finish(o, p, frame, nullptr);
}

}  // namespace
}  // namespace vkpt

int main(int argc, char** argv) {
  using namespace vkpt;
  // Past a file-size limit (ulimit -f) the kernel sends SIGXFSZ, whose default action
  // kills vkpt mid-write with the temporary left behind; ignored, write(2) fails with
  // EFBIG and the checked writer reports it and cleans up.
  signal(SIGXFSZ, SIG_IGN);
  std::unique_ptr<Cluster> cluster;
  try {
    cluster = JoinCluster(&argc, &argv);
  } catch (const Error& e) {
    PrintError("error", e.what());
    return 1;
  }
  if (cluster) {
    try {
      return RunRank(*cluster, argc, argv);
    } catch (const std::exception& e) {
      PrintError("error", cluster->Name(cluster->Rank()) + ": " + e.what());
      cluster->Abort(1);
    }
  }
  Options o;
  try {
    o = ParseOptions(argc, argv);
  } catch (const UsageError& e) {
    PrintError("usage error", e.what());
    return 2;
  }
  if (o.help) {
    std::fputs(HelpText().c_str(), stdout);
    return 0;
  }
  if (o.version) {
    std::printf("vkpt %s\ndistributed rendering: %s\n", VKPT_VERSION, ClusterSupport().c_str());
    return 0;
  }
  try {
    return Run(o);
  } catch (const Error& e) {
    PrintError("error", e.what());
  } catch (const std::bad_alloc&) {
    PrintError("error", o.scene + ": out of memory");
  } catch (const std::exception& e) {
    PrintError("error", o.scene + ": " + e.what());
  }
  return 1;
}

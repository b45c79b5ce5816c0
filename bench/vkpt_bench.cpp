// vkpt-bench: measures every tracer vkpt has on the same rays, in one run, and (when
// Embree 3 was found at configure time) Intel Embree's rtcIntersect1 beside them.
//
// Not a Google Benchmark binary on purpose: the figures only mean something as ratios
// between tracers over *identical* ray sets, cross-checked hit for hit, reported as one
// JSON object per run — a harness of repeated micro-benchmarks measures none of that.
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cpu/path_tracer.h"
#include "cpu/traversal.h"
#include "glb_writer.h"
#include "gltf/gltf_loader.h"
#include "image/image.h"
#include "procedural.h"
#include "render/light_table.h"
#include "render/render_scene.h"
#include "shared/estimator.h"
#include "shared/intersect.h"
#include "shared/rng.h"
#include "shared/sampling.h"
#include "util/atomic_write.h"
#include "util/error.h"
#include "util/parallel.h"
#include "vk/vk_renderer.h"

#ifdef VKPT_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

namespace vkpt::internal::bench {
namespace {

using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

struct Options {
  std::string scene;
  uint32_t procedural = 0;
  uint32_t width = 1024, height = 1024;
  unsigned threads = 0;  // 0: all cores
  bool json = false;
  bool markdown = false;  // one row of bench/README.md's table
  std::string quality;    // --quality REF.pfm: time to reach relMSE <= target
  double target = 1.2e-3;         // --target X: the relMSE --quality waits for
  std::string writeGlb;           // --write-glb FILE: the procedural scene as a glTF, no benchmark
  std::string splits = "object";  // --splits: the builder as compared with Embree's
  uint32_t leafSize = BvhBuildOptions{}.maxLeafSize;
  float traversalCost = BvhBuildOptions{}.traversalCost;  // SAH cost of a node visit
};

constexpr int kBuildRuns = 3;
constexpr int kTraceRuns = 3;  // ray timings: the fastest of three

[[noreturn]] void Usage(const std::string& why) {
  std::fprintf(stderr,
               "vkpt-bench: %s\nusage: vkpt-bench (--scene FILE | --procedural N) [--width W] [--height H] "
               "[--threads N] [--splits object|spatial|auto] [--leaf-size N] [--traversal-cost C] [--json | "
               "--markdown] [--quality REF.pfm [--target RELMSE]] [--write-glb FILE]\n",
               why.c_str());
  std::exit(2);
}

uint32_t Number(const char* opt, const char* text) {
  uint32_t v = 0;
  auto [end, ec] = std::from_chars(text, text + std::strlen(text), v);
  if (ec != std::errc() || *end || v == 0) Usage(std::string(opt) + " expects a positive number, got \"" + text + "\"");
  return v;
}

Options Parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) Usage(a + " needs a value");
      return argv[++i];
    };
    if (a == "--scene") o.scene = value();
    else if (a == "--procedural") o.procedural = Number("--procedural", value());
    else if (a == "--width") o.width = Number("--width", value());
    else if (a == "--height") o.height = Number("--height", value());
    else if (a == "--threads") o.threads = Number("--threads", value());
    else if (a == "--json") o.json = true;
    else if (a == "--markdown") o.markdown = true;
    else if (a == "--quality") o.quality = value();
    else if (a == "--target") {
      const char* v = value();
      char* end = nullptr;
      o.target = std::strtod(v, &end);
      if (*end || !(o.target > 0.0 && o.target < 1.0))
        Usage(std::string("--target expects a relMSE in (0, 1), got \"") + v + "\"");
    } else if (a == "--write-glb") o.writeGlb = value();
    else if (a == "--splits") {
      o.splits = value();
      if (!ParseSplitMode(o.splits)) Usage("--splits must be object, spatial or auto, got \"" + o.splits + "\"");
    }
    else if (a == "--leaf-size") o.leafSize = Number("--leaf-size", value());
    else if (a == "--traversal-cost") {
      const char* v = value();
      char* end = nullptr;
      o.traversalCost = std::strtof(v, &end);
      if (*end || !(o.traversalCost > 0.0f)) Usage(std::string("--traversal-cost expects a positive number, got \"") + v + "\"");
    }
    else if (a == "-h" || a == "--help") Usage("benchmarks BVH build, traversal and path tracing");
    else Usage("unknown option \"" + a + "\"");
  }
  if (o.scene.empty() == (o.procedural == 0)) Usage("give exactly one of --scene FILE and --procedural N");
  if (o.quality.empty() && o.target != Options{}.target) Usage("--target is the relMSE --quality waits for");
  if (!o.quality.empty() && o.markdown) Usage("--quality prints text or --json, not --markdown");
  if (!o.writeGlb.empty() && o.procedural == 0) Usage("--write-glb writes the --procedural scene");
  return o;
}

// The BVH the options ask for, built on `threads` threads.
BvhBuildOptions BuildOptions(const Options& o, unsigned threads) {
  BvhBuildOptions b;
  b.threads = threads;
  b.splits = *ParseSplitMode(o.splits);
  b.maxLeafSize = o.leafSize;
  b.traversalCost = o.traversalCost;
  return b;
}

// Rays per ParallelFor step: one ray is too short a task to take from a shared counter.
constexpr size_t kRayGrain = 256;

// Camera rays through pixel centres, then one cosine-weighted bounce from every hit:
// the same two ray sets for every tracer.
struct RaySets {
  std::vector<shader::RayQuery> camera, diffuse;
};

RaySets MakeRays(const RenderScene& rs, const shader::FrameParams& p, unsigned threads) {
  RaySets r;
  r.camera.resize(size_t(p.width) * p.height);
  for (uint32_t y = 0; y < p.height; ++y)
    for (uint32_t x = 0; x < p.width; ++x) {
      shader::Ray ray = shader::GenerateCameraRay(p, x, y, 0.5f, 0.5f);
      r.camera[size_t(y) * p.width + x] = {ray.origin, shader::kInfinity, ray.dir, 0};
    }
  std::vector<Hit> hits(r.camera.size());
  ParallelFor(hits.size(), threads, [&](size_t i) {
    hits[i] = IntersectClosest(rs, r.camera[i].origin, r.camera[i].dir, r.camera[i].tMax);
  }, kRayGrain);
  for (size_t i = 0; i < hits.size(); ++i) {
    if (hits[i].t < 0.0f) continue;
    const shader::Triangle& t = rs.triangles[hits[i].triangle];
    glm::vec3 ng = glm::normalize(glm::cross(t.e1, t.e2));
    if (glm::dot(ng, r.camera[i].dir) > 0.0f) ng = -ng;
    glm::vec3 p0 = t.v0 + hits[i].b1 * t.e1 + hits[i].b2 * t.e2;
    glm::vec4 u = shader::Random4(1u, uint32_t(i), 0u, 0u);
    glm::vec3 d = shader::FrameToWorld(shader::FrameFromNormal(ng), shader::SampleCosineHemisphere(u.x, u.y));
    r.diffuse.push_back({shader::OffsetRayOrigin(p0, ng), shader::kInfinity, d, 0});
  }
  return r;
}

struct TraceRun {
  double seconds = 0.0;
  std::vector<float> t;  // hit distance per ray, -1 for a miss (for cross-checks)
};

// The fastest of kTraceRuns runs of `trace` (all trace the same rays): this shared
// machine's timings drift by 10 % and more from one run to the next.
template <class Trace>
TraceRun Fastest(Trace trace) {
  TraceRun best = trace();
  for (int k = 1; k < kTraceRuns; ++k) {
    TraceRun run = trace();
    if (run.seconds < best.seconds) best = std::move(run);
  }
  return best;
}

TraceRun TraceCpu(const RenderScene& rs, const std::vector<shader::RayQuery>& rays, unsigned threads) {
  TraceRun run;
  run.t.resize(rays.size());
  auto t0 = Clock::now();
  ParallelFor(rays.size(), threads, [&](size_t i) {
    run.t[i] = IntersectClosest(rs, rays[i].origin, rays[i].dir, rays[i].tMax).t;
  }, kRayGrain);
  run.seconds = Seconds(t0);
  return run;
}

TraceRun TraceGpu(vk::GpuRenderer& gpu, const std::vector<shader::RayQuery>& rays) {
  TraceRun run;
  std::vector<shader::HitRecord> hits = gpu.Trace(rays, &run.seconds);
  run.t.reserve(hits.size());
  for (const shader::HitRecord& h : hits) run.t.push_back(h.t);
  return run;
}

// Rays whose hit distance differs between two tracers by more than float noise
// (different tracers round differently, and a ray grazing an edge may hit a neighbour).
uint64_t Mismatches(const TraceRun& a, const TraceRun& b) {
  uint64_t n = 0;
  for (size_t i = 0; i < a.t.size(); ++i) {
    bool ha = a.t[i] >= 0.0f, hb = b.t[i] >= 0.0f;
    if (ha != hb || (ha && std::abs(a.t[i] - b.t[i]) > 1e-4f * std::max(1.0f, a.t[i]))) ++n;
  }
  return n;
}

#ifdef VKPT_HAVE_EMBREE
struct Embree {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  double buildSeconds = 0.0;

  Embree(const RenderScene& rs, unsigned threads, RTCBuildQuality quality) {
    std::string config = "threads=" + std::to_string(threads);
    device = rtcNewDevice(config.c_str());
    if (!device) throw Error("Embree: rtcNewDevice failed");
    auto t0 = Clock::now();
    scene = rtcNewScene(device);
    rtcSetSceneBuildQuality(scene, quality);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), rs.triangles.size() * 3));
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), rs.triangles.size()));
    for (size_t i = 0; i < rs.triangles.size(); ++i) {
      const shader::Triangle& t = rs.triangles[i];
      glm::vec3 p[3] = {t.v0, t.v0 + t.e1, t.v0 + t.e2};
      for (int k = 0; k < 3; ++k) {
        v[9 * i + 3 * k + 0] = p[k].x;
        v[9 * i + 3 * k + 1] = p[k].y;
        v[9 * i + 3 * k + 2] = p[k].z;
        idx[3 * i + k] = unsigned(3 * i + k);
      }
    }
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene);
    buildSeconds = Seconds(t0);
  }
  ~Embree() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  TraceRun Trace(const std::vector<shader::RayQuery>& rays, unsigned threads) const {
    TraceRun run;
    run.t.resize(rays.size());
    auto t0 = Clock::now();
    ParallelFor(rays.size(), threads, [&](size_t i) {
      RTCIntersectContext ctx;
      rtcInitIntersectContext(&ctx);
      RTCRayHit rh{};
      rh.ray.org_x = rays[i].origin.x;
      rh.ray.org_y = rays[i].origin.y;
      rh.ray.org_z = rays[i].origin.z;
      rh.ray.dir_x = rays[i].dir.x;
      rh.ray.dir_y = rays[i].dir.y;
      rh.ray.dir_z = rays[i].dir.z;
      rh.ray.tnear = 0.0f;
      rh.ray.tfar = rays[i].tMax;
      rh.ray.mask = ~0u;
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(scene, &ctx, &rh);
      run.t[i] = rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? -1.0f : rh.ray.tfar;
    }, kRayGrain);
    run.seconds = Seconds(t0);
    return run;
  }
};
#endif

struct Report {
  std::map<std::string, std::optional<double>> numbers;
  std::string device;
  unsigned threads = 0;

  void Set(const std::string& key, std::optional<double> v) { numbers[key] = v; }
  std::optional<double> Get(const std::string& key) const {
    auto it = numbers.find(key);
    return it == numbers.end() ? std::nullopt : it->second;
  }
};

void PrintJson(const Report& r) {
  std::printf("{");
  for (const auto& [k, v] : r.numbers) {
    if (v) std::printf("\"%s\": %.6g, ", k.c_str(), *v);
    else std::printf("\"%s\": null, ", k.c_str());
  }
  std::string dev;
  for (char c : r.device) dev += (c == '"' || c == '\\') ? '_' : c;
  std::printf("\"device\": \"%s\", \"threads\": %u}\n", dev.c_str(), r.threads);
}

// | scene | threads | tris | build Mtri/s | Embree build (1 thread) | SAH | CPU cam | CPU diff |
// GPU cam | GPU diff | Embree cam | Embree diff | CPU PT | GPU PT | mismatches |
void PrintMarkdownRow(const Report& r, const std::string& scene) {
  auto f = [&](const char* key, const char* fmt) {
    std::optional<double> v = r.Get(key);
    char buf[64];
    if (!v) return std::string("n/a");
    std::snprintf(buf, sizeof buf, fmt, *v);
    return std::string(buf);
  };
  const bool one = r.threads == 1;
  std::printf("| %s | %u | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", scene.c_str(),
              r.threads, f("tris", "%.0f").c_str(), f("build_mtris_per_s", "%.2f").c_str(),
              f("embree_build_mtris_per_s", "%.2f").c_str(), f("sah_cost", "%.1f").c_str(),
              f(one ? "cpu_primary_mrays_s_1t" : "cpu_primary_mrays_s", "%.2f").c_str(),
              f(one ? "cpu_diffuse_mrays_s_1t" : "cpu_diffuse_mrays_s", "%.2f").c_str(),
              f("gpu_primary_mrays_s", "%.2f").c_str(), f("gpu_diffuse_mrays_s", "%.2f").c_str(),
              f("embree_primary_mrays_s", "%.2f").c_str(), f("embree_diffuse_mrays_s", "%.2f").c_str(),
              f("cpu_pt_msamples_s", "%.3f").c_str(), f("gpu_pt_msamples_s", "%.3f").c_str(),
              f("hit_mismatches", "%.0f").c_str());
}

void PrintTable(const Report& r) {
  auto line = [&](const char* what, const std::string& key, const char* unit, const char* embreeKey) {
    std::optional<double> v = r.Get(key);
    if (!v) {
      std::printf("  %-40s %12s\n", what, "n/a");
      return;
    }
    std::printf("  %-40s %12.3f %s", what, *v, unit);
    if (embreeKey) {
      std::optional<double> e = r.Get(embreeKey);
      if (e && *e > 0) std::printf("   (%.0f %% of Embree)", 100.0 * *v / *e);
    }
    std::printf("\n");
  };
  std::printf("vkpt-bench: %.0f triangles, %u threads, device: %s\n", r.Get("tris").value_or(0), r.threads,
              r.device.c_str());
  line("BVH build", "build_ms", "ms", nullptr);
  line("BVH build rate", "build_mtris_per_s", "Mtri/s", "embree_build_mtris_per_s");
  if (r.threads > 1) line("BVH build rate, 1 thread", "build_mtris_per_s_1t", "Mtri/s", "embree_build_mtris_per_s");
  line("SAH cost", "sah_cost", "", nullptr);
  line("nodes", "nodes", "", nullptr);
  line("triangle references in leaves", "references", "", nullptr);
  line("GPU bytes per triangle", "gpu_bytes_per_tri", "B", nullptr);
  line("CPU camera rays, 1 thread", "cpu_primary_mrays_s_1t", "Mrays/s", "embree_primary_mrays_s_1t");
  line("CPU diffuse rays, 1 thread", "cpu_diffuse_mrays_s_1t", "Mrays/s", "embree_diffuse_mrays_s_1t");
  // "N threads": the --threads count, which the GPU (LP_NUM_THREADS) and Embree use too.
  const std::string n = std::to_string(r.threads) + (r.threads == 1 ? " thread" : " threads");
  if (r.threads > 1) {
    line(("CPU camera rays, " + n).c_str(), "cpu_primary_mrays_s", "Mrays/s", "embree_primary_mrays_s");
    line(("CPU diffuse rays, " + n).c_str(), "cpu_diffuse_mrays_s", "Mrays/s", "embree_diffuse_mrays_s");
  }
  line(("GPU camera rays, " + n).c_str(), "gpu_primary_mrays_s", "Mrays/s", "embree_primary_mrays_s");
  line(("GPU diffuse rays, " + n).c_str(), "gpu_diffuse_mrays_s", "Mrays/s", "embree_diffuse_mrays_s");
  line("Embree camera rays, 1 thread", "embree_primary_mrays_s_1t", "Mrays/s", nullptr);
  line("Embree diffuse rays, 1 thread", "embree_diffuse_mrays_s_1t", "Mrays/s", nullptr);
  if (r.threads > 1) {
    line(("Embree camera rays, " + n).c_str(), "embree_primary_mrays_s", "Mrays/s", nullptr);
    line(("Embree diffuse rays, " + n).c_str(), "embree_diffuse_mrays_s", "Mrays/s", nullptr);
  }
  line("CPU path tracing", "cpu_pt_msamples_s", "Msamples/s", nullptr);
  line("GPU path tracing", "gpu_pt_msamples_s", "Msamples/s", nullptr);
  line("hit mismatches between tracers", "hit_mismatches", "rays", nullptr);
  line("peak host memory of the run (RSS)", "peak_rss_mib", "MiB", nullptr);
}

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

double Mrays(size_t n, double seconds) { return double(n) / seconds * 1e-6; }

// Build time: the best of kBuildRuns builds (the first in a process also pays the
// kernel for fresh pages; this machine's timings drift). Embree's is timed the same way.
// The one-thread figure is measured in the same run, for the thread scaling.
void MeasureBuild(const Scene& scene, const RenderScene& rs, const BvhBuildOptions& bvhOptions, unsigned threads,
                  double tris, Report& rep) {
  auto bestBuildMs = [&](unsigned buildThreads, double first) {
    BvhBuildOptions b = bvhOptions;
    b.threads = buildThreads;
    for (int k = 1; k < kBuildRuns; ++k) first = std::min(first, PrepareRenderScene(scene, b, false).bvhStats.buildMs);
    return first;
  };
  const double buildMs = bestBuildMs(threads, rs.bvhStats.buildMs);
  const double buildMs1 = threads == 1 ? buildMs : bestBuildMs(1, std::numeric_limits<double>::infinity());
  rep.Set("build_ms", buildMs);
  rep.Set("build_mtris_per_s", tris / buildMs * 1e-3);
  rep.Set("build_mtris_per_s_1t", tris / buildMs1 * 1e-3);
  rep.Set("sah_cost", rs.bvhStats.sahCost);
  rep.Set("nodes", rs.bvhStats.nodes);
  rep.Set("gpu_bytes_per_tri",
          (rs.triangles.size() * sizeof(shader::Triangle) + rs.gpuNodes.size() * sizeof(shader::WideBvhNode)) / tris);
}

// Full path tracing: 256×256 × 16 spp (background 1 if the scene has no lights).
shader::FrameParams PathTraceFrame(const RenderScene& rs, const Camera& cam) {
  shader::FrameParams pt = MakeFrameParams(rs, cam, 256, 256);
  pt.sampleCount = 16;
  pt.maxDepth = 32;
  pt.rrDepth = 3;
  if (rs.lights.empty()) pt.background = glm::vec3(1.0f);
  return pt;
}

// The CPU reference's closest hits on both ray sets (with `threads` threads, and timed
// with one thread too); every other tracer's hits are checked against them.
struct CpuHits {
  TraceRun camera, diffuse;
};

CpuHits MeasureCpu(const RenderScene& rs, const RaySets& rays, const shader::FrameParams& pt, unsigned threads,
                   Report& rep) {
  auto trace = [&](const std::vector<shader::RayQuery>& set, unsigned n) {
    return Fastest([&] { return TraceCpu(rs, set, n); });
  };
  CpuHits hits{trace(rays.camera, threads), trace(rays.diffuse, threads)};
  const CpuHits one = threads == 1 ? hits : CpuHits{trace(rays.camera, 1), trace(rays.diffuse, 1)};
  rep.Set("cpu_primary_mrays_s_1t", Mrays(rays.camera.size(), one.camera.seconds));
  rep.Set("cpu_diffuse_mrays_s_1t", Mrays(rays.diffuse.size(), one.diffuse.seconds));
  rep.Set("cpu_primary_mrays_s", Mrays(rays.camera.size(), hits.camera.seconds));
  rep.Set("cpu_diffuse_mrays_s", Mrays(rays.diffuse.size(), hits.diffuse.seconds));
  CpuRenderOptions cpuOpt;
  cpuOpt.threads = threads;
  RenderResult cpuPt = RenderCpu(rs, pt, cpuOpt);
  rep.Set("cpu_pt_msamples_s", 256.0 * 256.0 * pt.sampleCount / cpuPt.seconds * 1e-6);
  return hits;
}

// The Vulkan device's figures (null without one); returns the hits that differ from the CPU's.
uint64_t MeasureGpu(const RenderScene& rs, const RaySets& rays, const shader::FrameParams& pt, const CpuHits& cpu,
                    Report& rep) {
  rep.Set("gpu_primary_mrays_s", std::nullopt);
  rep.Set("gpu_diffuse_mrays_s", std::nullopt);
  rep.Set("gpu_pt_msamples_s", std::nullopt);
  uint64_t mismatches = 0;
  try {
    vk::Context ctx(vk::ContextOptions{});
    rep.device = ctx.DeviceName();
    vk::GpuRenderer gpu(ctx, rs);
    TraceRun gCam = Fastest([&] { return TraceGpu(gpu, rays.camera); });
    TraceRun gDif = Fastest([&] { return TraceGpu(gpu, rays.diffuse); });
    rep.Set("gpu_primary_mrays_s", Mrays(rays.camera.size(), gCam.seconds));
    rep.Set("gpu_diffuse_mrays_s", Mrays(rays.diffuse.size(), gDif.seconds));
    mismatches += Mismatches(cpu.camera, gCam) + Mismatches(cpu.diffuse, gDif);
    RenderResult g = gpu.Render(pt);
    rep.Set("gpu_pt_msamples_s", 256.0 * 256.0 * pt.sampleCount / g.seconds * 1e-6);
  } catch (const Error& e) {
    std::fprintf(stderr, "vkpt-bench: GPU figures skipped: %s\n", e.what());
    rep.device = "none";
  }
  return mismatches;
}

// Embree's figures (null without it); returns the hits that differ from the CPU's.
uint64_t MeasureEmbree([[maybe_unused]] const RenderScene& rs, [[maybe_unused]] const RaySets& rays,
                       [[maybe_unused]] const CpuHits& cpu, [[maybe_unused]] double tris,
                       [[maybe_unused]] unsigned threads, Report& rep) {
  for (const char* k : {"embree_primary_mrays_s", "embree_diffuse_mrays_s", "embree_primary_mrays_s_1t",
                        "embree_diffuse_mrays_s_1t", "embree_build_mtris_per_s"})
    rep.Set(k, std::nullopt);
  uint64_t mismatches = 0;
#ifdef VKPT_HAVE_EMBREE
  // Builders compared at MEDIUM (binned SAH, as vkpt's object splits); rays traced
  // through Embree's best tree, HIGH (with spatial splits).
  double buildSeconds = INFINITY;
  for (int k = 0; k < kBuildRuns; ++k)
    buildSeconds = std::min(buildSeconds, Embree(rs, 1, RTC_BUILD_QUALITY_MEDIUM).buildSeconds);
  rep.Set("embree_build_mtris_per_s", tris / buildSeconds * 1e-6);
  Embree e1(rs, 1, RTC_BUILD_QUALITY_HIGH);
  auto trace = [](const Embree& e, const std::vector<shader::RayQuery>& set, unsigned n) {
    return Fastest([&] { return e.Trace(set, n); });
  };
  TraceRun eCam1 = trace(e1, rays.camera, 1), eDif1 = trace(e1, rays.diffuse, 1);
  rep.Set("embree_primary_mrays_s_1t", Mrays(rays.camera.size(), eCam1.seconds));
  rep.Set("embree_diffuse_mrays_s_1t", Mrays(rays.diffuse.size(), eDif1.seconds));
  Embree en(rs, threads, RTC_BUILD_QUALITY_HIGH);
  TraceRun eCam = trace(en, rays.camera, threads), eDif = trace(en, rays.diffuse, threads);
  rep.Set("embree_primary_mrays_s", Mrays(rays.camera.size(), eCam.seconds));
  rep.Set("embree_diffuse_mrays_s", Mrays(rays.diffuse.size(), eDif.seconds));
  mismatches += Mismatches(cpu.camera, eCam) + Mismatches(cpu.diffuse, eDif);
#endif
  return mismatches;
}

void PrintReport(const Options& o, Report& rep) {
  // The whole run's peak: scene, trees, ray sets and hits, lavapipe's and Embree's memory.
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) == 0) rep.Set("peak_rss_mib", double(usage.ru_maxrss) / 1024.0);
  if (o.json) PrintJson(rep);
  else if (o.markdown)
    PrintMarkdownRow(rep, (o.procedural ? "procedural " + std::to_string(o.procedural)
                                        : o.scene.substr(o.scene.find_last_of('/') + 1)) +
                              (o.splits == "object" ? "" : ", " + o.splits + " splits"));
  else PrintTable(rep);
}

// --write-glb: the procedural scene as a file vkpt itself can render.
int WriteGlb(const Options& o) {
  const std::vector<uint8_t> glb = EncodeGlb(ProceduralScene(o.procedural));
  WriteFileAtomically(o.writeGlb, glb);
  std::printf("vkpt-bench: %s: %u triangles, %.1f MiB\n", o.writeGlb.c_str(), o.procedural, glb.size() / 1048576.0);
  return 0;
}

int Run(const Options& o) {
  if (!o.writeGlb.empty()) return WriteGlb(o);
  const unsigned threads = ThreadCount(o.threads);
  // lavapipe reads LP_NUM_THREADS when its device is created: set it first.
  setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 1);
  if (!o.quality.empty()) return Quality(o, threads);
  Report rep;
  rep.threads = threads;

  Scene scene = o.procedural ? ProceduralScene(o.procedural) : LoadGltf(o.scene);
  const BvhBuildOptions bvhOptions = BuildOptions(o, threads);
  RenderScene rs = PrepareRenderScene(scene, bvhOptions);
  // Triangles of the scene (not references: spatial splits duplicate some).
  const double tris = double(scene.triangles.size() - rs.degenerateTriangles);
  rep.Set("tris", tris);
  rep.Set("references", double(rs.bvhStats.references));
  MeasureBuild(scene, rs, bvhOptions, threads, tris, rep);

  const Camera cam = scene.cameras.empty() ? DefaultCamera(scene.bounds) : scene.cameras[0];
  RaySets rays = MakeRays(rs, MakeFrameParams(rs, cam, o.width, o.height), threads);
  rep.Set("rays_primary", double(rays.camera.size()));
  rep.Set("rays_diffuse", double(rays.diffuse.size()));
  const shader::FrameParams pt = PathTraceFrame(rs, cam);
  const CpuHits cpu = MeasureCpu(rs, rays, pt, threads, rep);
  uint64_t mismatches = MeasureGpu(rs, rays, pt, cpu, rep);
  mismatches += MeasureEmbree(rs, rays, cpu, tris, threads, rep);
  rep.Set("hit_mismatches", double(mismatches));
  PrintReport(o, rep);
  return 0;
}

}  // namespace
}  // namespace vkpt::internal::bench

int main(int argc, char** argv) {
  vkpt::internal::bench::Options o = vkpt::internal::bench::Parse(argc, argv);
  try {
    return vkpt::internal::bench::Run(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vkpt-bench: error: %s\n", e.what());
    return 1;
  }
}

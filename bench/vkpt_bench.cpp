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

#include "bench_options.h"
#include "cpu/path_tracer.h"
#include "cpu/traversal.h"
#include "glb_writer.h"
#include "gltf/gltf_loader.h"
#include "image/image.h"
#include "procedural.h"
#include "quality.h"
#include "ray_runs.h"
#include "render/light_table.h"
#include "render/render_scene.h"
#include "report.h"
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

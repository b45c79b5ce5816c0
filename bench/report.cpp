#include "report.h"

#include <cmath>
#include <cstdio>

namespace vkpt::internal::bench {

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

}  // namespace vkpt::internal::bench

// The ray sets every tracer of vkpt-bench traces, and the timed runs of them on the CPU
// and the Vulkan device, cross-checked hit for hit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "bench_options.h"
#include "render/render_scene.h"
#include "shared/estimator.h"
#include "vk/vk_renderer.h"

namespace vkpt::internal::bench {

// Rays per ParallelFor step: one ray is too short a task to take from a shared counter.
constexpr size_t kRayGrain = 256;

// Camera rays through pixel centres, then one cosine-weighted bounce from every hit:
// the same two ray sets for every tracer.
struct RaySets {
  std::vector<shader::RayQuery> camera, diffuse;
};

RaySets MakeRays(const RenderScene& rs, const shader::FrameParams& p, unsigned threads);

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

TraceRun TraceCpu(const RenderScene& rs, const std::vector<shader::RayQuery>& rays, unsigned threads);
TraceRun TraceGpu(vk::GpuRenderer& gpu, const std::vector<shader::RayQuery>& rays);

// Rays whose hit distance differs between two tracers by more than float noise
// (different tracers round differently, and a ray grazing an edge may hit a neighbour).
uint64_t Mismatches(const TraceRun& a, const TraceRun& b);

}  // namespace vkpt::internal::bench

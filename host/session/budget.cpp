#include "session/budget.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "session/noise_estimate.h"

namespace vkpt::internal {
namespace {

constexpr uint32_t kFirstDecision = 16;  // samples before a pixel's variance is trusted

}  // namespace

const char* StopReasonName(StopReason r) {
  switch (r) {
    case StopReason::kTime: return "time";
    case StopReason::kNoiseTarget: return "noise_target";
    case StopReason::kConverged: return "converged";
    case StopReason::kSignal: return "signal";
    default: return "spp";
  }
}

uint32_t NextDecisionPoint(uint32_t spp, uint32_t chunkSpp) {
  const uint64_t step = std::max(chunkSpp, 1u);
  for (uint64_t point = kFirstDecision;; point += std::max<uint64_t>(8, point / 4)) {
    const uint64_t aligned = (point + step - 1) / step * step;
    if (aligned > spp) return uint32_t(std::min<uint64_t>(aligned, UINT32_MAX));
  }
}

double FinishedFraction(const RenderBudget& budget, double spp, double seconds, double noise) {
  double f = spp / budget.spp;
  if (budget.seconds) f = std::max(f, seconds / *budget.seconds);
  if (budget.noiseTarget && std::isfinite(noise)) f = std::max(f, *budget.noiseTarget / noise);
  return std::min(f, 1.0);
}

Decision Decide(const RenderBudget& budget, const FrameSums& sums, std::vector<uint8_t>& active) {
  Decision d;
  d.noise = EstimatedRelMse(sums);
  char report[160];
  std::snprintf(report, sizeof report, ", estimated relMSE %.4g", d.noise);
  d.report = report;
  if (budget.adaptive) {
    d.activePixels = UpdateActivePixels(sums, budget.adaptiveThreshold, active);
    std::snprintf(report, sizeof report, ", %llu of %zu pixels active", (unsigned long long)d.activePixels,
                  active.size());
    d.report += report;
    if (d.activePixels == 0) d.stop = StopReason::kConverged;
  } else {
    d.activePixels = sums.pixels.size();
  }
  if (budget.noiseTarget && d.noise <= *budget.noiseTarget) d.stop = StopReason::kNoiseTarget;
  return d;
}

}  // namespace vkpt::internal

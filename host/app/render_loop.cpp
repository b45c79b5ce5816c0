#include "app/render_loop.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

#include "image/noise_estimate.h"
#include "util/graceful_stop.h"

namespace vkpt {
namespace {

constexpr uint32_t kFirstDecision = 16;  // samples before a pixel's variance is trusted

double Since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

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
  double f = spp / budget.maxSpp;
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

uint32_t NextPassSpp(const RenderBudget& budget, const PassPlan& plan, double passSeconds) {
  if (plan.done >= budget.maxSpp) return 0;
  uint32_t n = 1;
  if (plan.lastPass > 0) {
    const double fit = plan.secondsPerSpp > 0.0 ? passSeconds / plan.secondsPerSpp : 1e9;
    n = uint32_t(std::clamp(std::floor(fit), 1.0, 2.0 * plan.lastPass));
    if (budget.seconds) {
      const double left = (*budget.seconds - plan.elapsed) / std::max(plan.secondsPerSpp, 1e-9);
      if (left < 1.0) return 0;
      n = std::min(n, uint32_t(std::min(left, 1e9)));
    }
  }
  n = std::min(n, budget.maxSpp - plan.done);
  if (budget.Decisions()) n = std::min(n, NextDecisionPoint(plan.done, budget.chunkSpp) - plan.done);
  return n;
}

ProgressiveRender RenderProgressively(FrameRenderer& renderer, const RenderBudget& budget,
                                      const RenderLoopHooks& hooks) {
  ProgressiveRender out;
  const bool decisions = budget.Decisions();
  std::vector<uint8_t> active;  // empty: every pixel
  FrameSums sums;
  bool fresh = false;  // `sums` holds every sample taken
  PassPlan plan;
  double noise = INFINITY;
  const auto t0 = std::chrono::steady_clock::now();
  double lastCheckpoint = 0.0;
  auto fraction = [&](double passDone) { return FinishedFraction(budget, passDone, Since(t0), noise); };
  for (;;) {
    if (GracefulStop::Signal()) {
      out.stoppedBy = StopReason::kSignal;
      out.signal = GracefulStop::Signal();
      break;
    }
    plan.elapsed = Since(t0);
    const uint32_t n = NextPassSpp(budget, plan);
    if (n == 0) {
      out.stoppedBy = plan.done >= budget.maxSpp ? StopReason::kSpp : StopReason::kTime;
      break;
    }
    const auto passStart = std::chrono::steady_clock::now();
    std::function<void(double)> progress;
    if (hooks.progress) progress = [&](double f) { hooks.progress(fraction(plan.done + f * n)); };
    renderer.AddSamples(plan.done, n, active, progress);
    fresh = false;
    const double passSeconds = Since(passStart);
    plan.done += n;
    plan.lastPass = n;
    plan.secondsPerSpp = passSeconds / n;
    out.sppPerPass.push_back(n);

    char report[160];
    std::snprintf(report, sizeof report, "pass %zu: samples %u..%u in %.3f s", out.sppPerPass.size(), plan.done - n,
                  plan.done - 1, passSeconds);
    std::string line = report;
    std::optional<StopReason> stop;
    if (decisions && plan.done == NextDecisionPoint(plan.done - 1, budget.chunkSpp)) {
      sums = renderer.Sums();
      fresh = true;
      const Decision d = Decide(budget, sums, active);
      noise = d.noise;
      line += d.report;
      stop = d.stop;
    }
    if (hooks.passReport) hooks.passReport(line);
    if (stop) {
      out.stoppedBy = *stop;
      break;
    }
    if (budget.checkpointSeconds > 0.0 && hooks.checkpoint && Since(t0) - lastCheckpoint >= budget.checkpointSeconds &&
        plan.done < budget.maxSpp) {
      if (!fresh) sums = renderer.Sums();
      fresh = true;
      hooks.checkpoint(sums, plan.done);
      ++out.checkpoints;
      lastCheckpoint = Since(t0);
    }
  }
  out.sums = fresh ? std::move(sums) : renderer.Sums();
  out.spp = plan.done;
  out.engine = renderer.Engine();
  out.seconds = Since(t0);
  out.estimatedRelMse = EstimatedRelMse(out.sums);
  out.samples = TotalSamples(out.sums);
  out.activePixels =
      active.empty() ? out.sums.pixels.size() : uint64_t(std::count(active.begin(), active.end(), uint8_t(1)));
  return out;
}

}  // namespace vkpt

#include "session/local_passes.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace vkpt::internal {
namespace {

double Since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

uint32_t NextPassSpp(const PassPlan& plan, uint32_t limit, std::optional<double> secondsLeft, double passSeconds) {
  if (plan.done >= limit) return 0;
  uint32_t n = 1;
  if (plan.lastPass > 0) {
    const double fit = plan.secondsPerSpp > 0.0 ? passSeconds / plan.secondsPerSpp : 1e9;
    n = uint32_t(std::clamp(std::floor(fit), 1.0, 2.0 * plan.lastPass));
    if (secondsLeft) {
      const double left = *secondsLeft / std::max(plan.secondsPerSpp, 1e-9);
      if (left < 1.0) return 0;
      n = std::min(n, uint32_t(std::min(left, 1e9)));
    }
  }
  return std::min(n, limit - plan.done);
}

uint32_t LocalPasses::Advance(const SampleRequest& request) {
  // A stop ends the render between passes: the pass under way is always finished.
  if (request.stop && request.stop()) return 0;
  plan_.done = request.done;
  std::optional<double> secondsLeft;
  if (request.deadline) secondsLeft = -Since(*request.deadline);
  const uint32_t n = NextPassSpp(plan_, request.limit, secondsLeft);
  if (n == 0) return 0;
  std::function<void(double)> progress;
  if (request.progress) progress = [&](double f) { request.progress(request.done + f * n); };
  const auto start = std::chrono::steady_clock::now();
  chunked_.AddSamples(request.done, n, request.active, progress);
  plan_.lastPass = n;
  plan_.secondsPerSpp = Since(start) / n;
  return n;
}

}  // namespace vkpt::internal

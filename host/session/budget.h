// What ends a render and when it is judged: --spp (an upper bound), --time, and
// --noise-target with adaptive sampling, whose decisions fall at fixed sample counts.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "render/film.h"

namespace vkpt::internal {

// The spp bound of a render given no spp: kDefaultSpp, or kBudgetMaxSpp given a time or
// noise target.
constexpr uint32_t kDefaultSpp = 64;
constexpr uint32_t kBudgetMaxSpp = 65536;

struct RenderBudget {
  uint32_t spp = kDefaultSpp;         // --spp: no pixel takes more samples
  std::optional<double> seconds;      // --time: rendering seconds
  std::optional<double> noiseTarget;  // --noise-target: estimated relMSE to reach
  bool adaptive = false;              // --adaptive: converged pixels stop taking samples
  double adaptiveThreshold = 1e-3;    // a pixel's estimated error below which it stops
  double checkpointSeconds = 0.0;     // --checkpoint: seconds between writes (0: none)
  uint32_t chunkSpp = 1;              // --chunk: decisions fall between chunks
  bool Decisions() const { return adaptive || noiseTarget.has_value(); }
};

// A budget as a user states it, the command line and the library alike; what is not
// stated takes its default here.
struct BudgetRequest {
  std::optional<uint32_t> spp;  // default kDefaultSpp, or kBudgetMaxSpp given a time or noise target
  std::optional<double> seconds;
  std::optional<double> noiseTarget;
  std::optional<bool> adaptive;  // default: on with a noise target, whose threshold it takes
  double checkpointSeconds = 0.0;
  uint32_t chunkSpp = 1;
};
// Inline: the command line's option parsing (and its fuzz target) needs it alone.
inline RenderBudget BudgetFor(const BudgetRequest& r) {
  RenderBudget b;
  b.spp = r.spp.value_or(r.seconds || r.noiseTarget ? kBudgetMaxSpp : kDefaultSpp);
  b.seconds = r.seconds;
  b.noiseTarget = r.noiseTarget;
  b.adaptive = r.adaptive.value_or(r.noiseTarget.has_value());
  if (r.noiseTarget) b.adaptiveThreshold = *r.noiseTarget;
  b.checkpointSeconds = r.checkpointSeconds;
  b.chunkSpp = r.chunkSpp;
  return b;
}

// kConverged: adaptive sampling without a noise target found every pixel below its
// threshold before --spp.
enum class StopReason { kSpp, kTime, kNoiseTarget, kConverged, kSignal };
const char* StopReasonName(StopReason r);  // "spp", "time", "noise_target", "converged", "signal"

// Adaptive decisions and noise checks happen only when the render reaches one of these
// sample counts, never at a moment set by the clock, so that for a given seed and device
// the image depends on the samples taken alone: 16, 24, 32, 40, 50, … (each a quarter
// more, at least 8) rounded up to whole chunks of `chunkSpp` (16, 32, 48, 64, 80, 96,
// 128, … for 16), so that no decision falls inside a chunk and an MPI job, which deals
// whole chunks, makes the decisions a single process makes.
uint32_t NextDecisionPoint(uint32_t spp, uint32_t chunkSpp);

// The finished fraction of a render at `spp` samples per pixel after `seconds`, whose
// last decision estimated `noise` (infinite before the first): of the spp bound, the
// time, or (as relMSE falls as 1/n) the noise target, whichever is nearest.
double FinishedFraction(const RenderBudget& budget, double spp, double seconds, double noise);

// What a decision point finds in the sums so far: their estimated relMSE, with adaptive
// sampling the pixels that go on (`active`, empty: every pixel), and whether the render
// stops there.
struct Decision {
  double noise = 0.0;
  uint64_t activePixels = 0;
  std::optional<StopReason> stop;
  std::string report;  // ", estimated relMSE …[, N of M pixels active]"
};
Decision Decide(const RenderBudget& budget, const FrameSums& sums, std::vector<uint8_t>& active);

}  // namespace vkpt::internal

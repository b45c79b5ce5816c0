// The render as a loop of passes under budgets: --spp (an upper bound), --time, and
// --noise-target with adaptive sampling; --checkpoint writes the image meanwhile, and a
// GracefulStop signal ends the loop after its pass. Either backend's FrameRenderer.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "image/film.h"

namespace vkpt {

struct RenderBudget {
  uint32_t maxSpp = 64;               // --spp: no pixel takes more samples
  std::optional<double> seconds;      // --time: rendering seconds
  std::optional<double> noiseTarget;  // --noise-target: estimated relMSE to reach
  bool adaptive = false;              // --adaptive: converged pixels stop taking samples
  double adaptiveThreshold = 1e-3;    // a pixel's estimated error below which it stops
  double checkpointSeconds = 0.0;     // --checkpoint: seconds between writes (0: none)
  uint32_t chunkSpp = 1;              // --chunk: decisions fall between chunks
  bool Decisions() const { return adaptive || noiseTarget.has_value(); }
};

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

// How many samples per pixel the next pass takes: about `passSeconds` of work at the rate
// of the last pass (at most twice its samples), within the time left and the --spp
// bound, and never past the next decision point; 0 when the time left fits no sample.
struct PassPlan {
  uint32_t done = 0;           // samples per pixel so far
  uint32_t lastPass = 0;       // samples of the last pass (0: none yet)
  double secondsPerSpp = 0.0;  // of the last pass
  double elapsed = 0.0;        // rendering seconds so far
};
uint32_t NextPassSpp(const RenderBudget& budget, const PassPlan& plan, double passSeconds = 1.0);

struct ProgressiveRender {
  FrameSums sums;
  std::vector<uint32_t> sppPerPass;
  uint32_t spp = 0;      // samples per pixel of the passes (adaptive: the most any pixel has)
  uint64_t samples = 0;  // every pixel's samples added up
  StopReason stoppedBy = StopReason::kSpp;
  int signal = 0;                // kSignal: which one
  double seconds = 0.0;          // the loop, checkpoints included
  double estimatedRelMse = 0.0;  // of the final sums (noise_estimate.h)
  uint64_t activePixels = 0;     // adaptive: pixels still taking samples at the end
  uint32_t checkpoints = 0;      // images written during the render
  std::string engine;            // the renderer's, at the end
};

struct RenderLoopHooks {
  std::function<void(double)> progress;                            // finished fraction, now and then
  std::function<void(const FrameSums&, uint32_t spp)> checkpoint;  // write the image so far
  std::function<void(const std::string&)> passReport;              // a line per pass (-v)
};

ProgressiveRender RenderProgressively(FrameRenderer& renderer, const RenderBudget& budget,
                                      const RenderLoopHooks& hooks = {});

}  // namespace vkpt

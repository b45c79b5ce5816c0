// A render session: one frame from a sample source (session/sample_source.h) under the
// budgets (session/budget.h), as one loop over named steps — ask the source for samples,
// judge the frame at decision points, write checkpoints — then the AOV pass and the
// denoiser when asked. A single process and an MPI job's rank 0 run this same loop; only
// their sources differ. Its result is the one every report and file is made from.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "cluster/rank_share.h"
#include "image/image.h"
#include "render/denoise.h"
#include "render/film.h"
#include "session/budget.h"
#include "session/sample_source.h"

namespace vkpt::internal {

// A rendered frame and how it came about.
struct RenderedFrame {
  FrameSums sums;                 // every sample taken, and the renderer's counters
  Image image;                    // the sums through a Film: mean and variance per pixel
  AovSums aovs;                   // the AOV pass's sums (empty without one)
  std::optional<Image> denoised;  // --denoise
  std::vector<uint32_t> sppPerPass;
  uint32_t spp = 0;      // samples per pixel of the passes (adaptive: the most any pixel has)
  uint64_t samples = 0;  // every pixel's samples added up
  StopReason stoppedBy = StopReason::kSpp;
  double estimatedRelMse = 0.0;     // of the final sums (session/noise_estimate.h)
  uint64_t activePixels = 0;        // adaptive: pixels still taking samples at the end
  uint32_t checkpoints = 0;         // images written during the render
  uint32_t checkpointFailures = 0;  // checkpoints that could not be written (the render went on)
  std::string engine;               // the source's, at the end
  std::vector<RankShare> ranks;     // an MPI job's ranks (empty for one process)
  double seconds = 0.0;             // the loop, checkpoints included
  double aovSeconds = 0.0;
  double denoiseSeconds = 0.0;
};

// Runs the filter's iterations on a backend (render/denoise.h); nothing once stopped.
using Denoiser = std::function<std::optional<std::vector<glm::vec4>>(const DenoiseInput&, const StopFilter&)>;

struct SessionSettings {
  RenderBudget budget;
  std::string checkpointPath;  // --checkpoint writes the image so far here (with budget.checkpointSeconds)
  DisplayTransform display;    // of the checkpoint's PNG
  bool aovPass = false;        // render the AOV pass after the frame (--aov, --denoise)
  bool aovIds = false;         // the AOV pass finds each pixel centre's triangle (the id AOVs)
  Denoiser denoise;            // --denoise: filter the image (needs the AOV pass)
  // Whether to stop between passes (a signal, a caller's cancel): kSignal. Empty: never.
  std::function<bool()> stop;
};

struct SessionHooks {
  std::function<void(double)> progress;             // finished fraction, now and then
  std::function<void(const std::string&)> report;   // a line per pass and checkpoint (-v)
  std::function<void(const std::string&)> warning;  // the first checkpoint that could not be written
};

RenderedFrame RenderSession(SampleSource& source, const SessionSettings& settings, const SessionHooks& hooks = {});

// A frame's image, estimated relMSE and sample count, from its sums.
void ResolveSums(RenderedFrame& frame);

// After a frame's samples: the AOV pass and the filter as `settings` ask (RenderSession's
// last steps, for a frame whose samples were taken another way: a progressive view).
void FinishFrame(SampleSource& source, const SessionSettings& settings, RenderedFrame& frame);

// The samples of the AOV pass: the first kAovSamples of the render's (fewer if it took fewer).
constexpr uint32_t kAovSamples = 16;

}  // namespace vkpt::internal

#include "session/render_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "image/image.h"
#include "session/noise_estimate.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

using Clock = std::chrono::steady_clock;

double Since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The loop's state between steps.
class FrameLoop {
 public:
  FrameLoop(SampleSource& source, const SessionSettings& settings, const SessionHooks& hooks)
      : source_(source), settings_(settings), budget_(settings.budget), hooks_(hooks) {
    if (budget_.seconds)
      deadline_ = start_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(*budget_.seconds));
  }

  RenderedFrame Run() {
    while (!stoppedBy_.has_value()) {
      const uint32_t point = budget_.Decisions() ? NextDecisionPoint(done_, budget_.chunkSpp) : UINT32_MAX;
      const uint32_t n = Step(std::min(budget_.spp, point));
      if (n == 0) {
        stoppedBy_ = done_ >= budget_.spp ? StopReason::kSpp : stopped_ ? StopReason::kSignal : StopReason::kTime;
        break;
      }
      std::string line = PassLine(n);
      if (done_ == point) line += Judge();
      if (hooks_.report) hooks_.report(line);
      if (!stoppedBy_ && done_ < budget_.spp) Checkpoint();
    }
    return Result();
  }

 private:
  // Whether settings_.stop has said to stop: once it has, the render stays stopped.
  bool Stopped() {
    if (!stopped_) stopped_ = settings_.stop();
    return stopped_;
  }

  // Asks the source for samples before `limit`: how many it added.
  uint32_t Step(uint32_t limit) {
    SampleRequest request{done_, limit, active_, deadline_, {}, {}};
    if (settings_.stop) request.stop = [this] { return Stopped(); };
    if (hooks_.progress) request.progress = [this](double spp) { hooks_.progress(Fraction(spp)); };
    const auto t0 = Clock::now();
    const uint32_t n = source_.Advance(request);
    stepSeconds_ = Since(t0);
    done_ += n;
    if (n) {
      passes_.push_back(n);
      fresh_ = false;
    }
    if (n && hooks_.progress) hooks_.progress(Fraction(done_));
    return n;
  }

  // At a decision point: the noise, the pixels that go on, and perhaps the end.
  std::string Judge() {
    TakeSums();
    const Decision d = Decide(budget_, sums_, active_);
    noise_ = d.noise;
    activePixels_ = d.activePixels;
    if (d.stop) stoppedBy_ = *d.stop;
    return d.report;
  }

  void Checkpoint() {
    if (budget_.checkpointSeconds <= 0.0 || settings_.checkpointPath.empty() ||
        Since(start_) - lastCheckpoint_ < budget_.checkpointSeconds)
      return;
    TakeSums();
    lastCheckpoint_ = Since(start_);
    // A checkpoint that cannot be written (a full disk) leaves the last one in place; the
    // render goes on, and the final write will fail, or succeed, on its own.
    try {
      WriteImage(ResolveFilm(sums_), settings_.checkpointPath, settings_.display);
    } catch (const Error& e) {
      if (++checkpointFailures_ == 1 && hooks_.warning)
        hooks_.warning(std::string("a checkpoint could not be written, the render goes on: ") + e.what());
      return;
    }
    ++checkpoints_;
    if (hooks_.report)
      hooks_.report("checkpoint: " + settings_.checkpointPath + " at " + std::to_string(done_) + " spp");
  }

  // sums_ = every sample taken; the old copy is freed first (one frame of sums, not two).
  void TakeSums() {
    if (fresh_) return;
    sums_ = FrameSums{};
    sums_ = source_.Sums();
    fresh_ = true;
  }

  std::string PassLine(uint32_t n) const {
    char line[96];
    std::snprintf(line, sizeof line, "pass %zu: samples %u..%u in %.3f s", passes_.size(), done_ - n, done_ - 1,
                  stepSeconds_);
    return line;
  }

  double Fraction(double spp) const { return FinishedFraction(budget_, spp, Since(start_), noise_); }

  RenderedFrame Result() {
    RenderedFrame r;
    TakeSums();
    r.sums = std::move(sums_);
    r.ranks = source_.Finish();
    r.stoppedBy = *stoppedBy_;
    r.sppPerPass = std::move(passes_);
    r.spp = done_;
    r.engine = source_.Engine();
    r.seconds = Since(start_);
    ResolveSums(r);
    r.activePixels = active_.empty() ? r.sums.pixels.size() : activePixels_;
    r.checkpoints = checkpoints_;
    r.checkpointFailures = checkpointFailures_;
    return r;
  }

  SampleSource& source_;
  const SessionSettings& settings_;
  const RenderBudget& budget_;
  const SessionHooks& hooks_;
  const Clock::time_point start_ = Clock::now();
  std::optional<Clock::time_point> deadline_;
  std::optional<StopReason> stoppedBy_;
  bool stopped_ = false;  // settings_.stop said so
  uint32_t done_ = 0;
  std::vector<uint32_t> passes_;
  double stepSeconds_ = 0.0;
  std::vector<uint8_t> active_;  // empty: every pixel
  uint64_t activePixels_ = 0;
  double noise_ = INFINITY;  // of the last decision
  FrameSums sums_;
  bool fresh_ = false;  // sums_ holds every sample taken
  uint32_t checkpoints_ = 0;
  uint32_t checkpointFailures_ = 0;
  double lastCheckpoint_ = 0.0;
};

}  // namespace

void ResolveSums(RenderedFrame& frame) {
  frame.image = ResolveFilm(frame.sums);
  frame.estimatedRelMse = EstimatedRelMse(frame.sums);
  frame.samples = TotalSamples(frame.sums);
}

RenderedFrame RenderSession(SampleSource& source, const SessionSettings& settings, const SessionHooks& hooks) {
  RenderedFrame frame = FrameLoop(source, settings, hooks).Run();
  FinishFrame(source, settings, frame);
  return frame;
}

void FinishFrame(SampleSource& source, const SessionSettings& settings, RenderedFrame& frame) {
  // A render its caller stopped ends soon after: the AOV pass takes one sample, and the
  // filter does not run (or is abandoned between iterations when the stop comes later).
  const bool stopped = frame.stoppedBy == StopReason::kSignal;
  const bool filter = settings.denoise && !stopped;
  if (settings.aovPass || filter) {
    const auto t0 = Clock::now();
    frame.aovs = source.RenderAovs({std::min(stopped ? 1u : kAovSamples, frame.spp), settings.aovIds});
    frame.aovSeconds = Since(t0);
  }
  if (filter) {
    const auto t0 = Clock::now();
    const DenoiseInput input = PrepareDenoise(frame.image, frame.aovs);
    if (const auto filtered = settings.denoise(input, settings.stop)) frame.denoised = FinishDenoise(input, *filtered);
    frame.denoiseSeconds = Since(t0);
  }
}

}  // namespace vkpt::internal

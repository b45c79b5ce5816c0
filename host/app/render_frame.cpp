#include "app/render_frame.h"

#include <signal.h>

#include <cstdio>
#include <string>
#include <vector>

#include "app/report.h"
#include "app/run_stats.h"
#include "image/image.h"
#include "session/aov.h"
#include "session/local_passes.h"
#include "util/atomic_write.h"
#include "util/graceful_stop.h"

namespace vkpt {

namespace {

// SIGINT and SIGTERM end a render between passes (util/graceful_stop.h).
bool SignalArrived() { return GracefulStop::Signal() != 0; }

}  // namespace

SessionSettings SettingsFromOptions(const Options& o, const RenderBackend& backend) {
  SessionSettings s;
  s.budget = o.Budget();
  s.checkpointPath = o.out;
  s.display = o.Display();
  s.aovPass = NeedsAovPass(o.aovs);
  s.aovIds = WantsIds(o.aovs);
  if (o.denoise) s.denoise = backend.MakeDenoiser();
  s.stop = SignalArrived;
  return s;
}

namespace {

SessionHooks HooksFromOptions(const Options& o) {
  SessionHooks hooks;
  hooks.progress = ProgressLine();
  hooks.warning = [](const std::string& line) {
    EndProgressLine();
    std::fprintf(stderr, "vkpt: warning: %s\n", line.c_str());
  };
  // Flushed line by line: a script reading a pipe sees each pass as it ends.
  if (o.verbose)
    hooks.report = [](const std::string& line) {
      std::printf("  %s\n", line.c_str());
      std::fflush(stdout);
    };
  return hooks;
}

}  // namespace

RenderedFrame Render(SampleSource& source, const SessionSettings& settings, const Options& o) {
  RenderedFrame frame = RenderSession(source, settings, HooksFromOptions(o));
  EndProgressLine();
  return frame;
}

RenderedFrame RenderReference(const Prepared& p, const Options& o) {
  const RenderBackend cpu(nullptr, p.rs(), o.threads);
  const std::unique_ptr<FrameRenderer> frame = cpu.BeginFrame(p.frame.params, 0);
  LocalPasses source(*frame, o.chunkSpp);
  SessionSettings settings;
  settings.budget.maxSpp = o.spp;
  settings.budget.chunkSpp = o.chunkSpp;
  settings.stop = SignalArrived;
  return Render(source, settings, Options{});
}

namespace {

// The image files: --out (denoised with --denoise, the raw one beside it), its AOVs and
// the names of their ids.
std::vector<std::string> WriteFiles(const RenderedFrame& frame, const Options& o, const LoadedScene& scene) {
  std::vector<std::string> files =
      WriteImageWithAovs(frame.denoised ? *frame.denoised : frame.image,
                         ResolveAovs(o.aovs, frame.aovs, frame.sums, frame.image, scene.IdsOf()), o.out, o.Display(),
                         WantsIds(o.aovs) ? scene.IdsJson() : "");
  if (frame.denoised) {
    files.push_back(SiblingPath(o.out, "raw"));
    WriteImage(frame.image, files.back(), o.Display());
  }
  return files;
}

}  // namespace

int Finish(const Options& o, Prepared& p, const RenderedFrame& frame, const RenderedFrame* reference,
           const RenderBackend& backend, std::string* frameStats) {
  RunTimes& times = p.times();
  times.render = frame.seconds;
  times.aov = frame.aovSeconds;
  times.denoise = frame.denoiseSeconds;
  PhaseTimer phase;
  const std::vector<std::string> files = WriteFiles(frame, o, *p.loaded);
  phase.Lap(times.write);
  int status = reference ? CompareBackends(*reference, frame, o) : 0;
  PrintRenderReport(p.scene(), p.rs(), frame, o, files, backend.DenoiserName());
  const vk::Context* device = p.loaded->Device();
  const uint32_t validationMessages = device ? device->ValidationMessages() : 0;
  if (validationMessages) {
    std::fprintf(stderr, "vkpt: %u Vulkan validation message(s) were reported\n", validationMessages);
    status = 3;
  }
  if (const int sig = GracefulStop::Signal()) {
    std::fprintf(stderr, "vkpt: interrupted by %s: %s holds the %u spp rendered (%s)\n",
                 sig == SIGTERM ? "SIGTERM" : "SIGINT", o.out.c_str(), frame.spp,
                 frame.stoppedBy == StopReason::kSignal ? "stopped early" : "the render had finished");
    status = 128 + sig;
  }
  if (!o.stats.empty() || frameStats) {
    times.total = SecondsSince(p.start);
    const std::string json =
        StatsJson(o, {p.scene(), p.rs(), frame, reference, times, validationMessages, status, files, p.frame.memory});
    if (frameStats) *frameStats = json;
    else WriteFileAtomically(o.stats, {reinterpret_cast<const uint8_t*>(json.data()), json.size()});
  }
  return status;
}

}  // namespace vkpt

#include "app/render_frame.h"

#include <signal.h>

#include <cstdio>
#include <string>
#include <vector>

#include "app/report.h"
#include "app/run_stats.h"
#include "image/aov_files.h"
#include "image/image.h"
#include "session/aov.h"
#include "util/atomic_write.h"
#include "util/graceful_stop.h"

namespace vkpt::internal {

RenderedFrame RenderReference(Prepared& p, const Options& o) {
  SessionSettings settings;
  settings.budget.spp = o.Budget().spp;
  settings.budget.chunkSpp = o.api.render.chunkSpp;
  settings.stop = GracefulStop::Arrived;
  SessionHooks hooks;
  hooks.progress = ProgressLine();
  const RenderedFrame reference = RenderOnCpu(p.scene(), p.view, settings, hooks);
  EndProgressLine();
  return reference;
}

namespace {

// The image files: --out (denoised with --denoise, the raw one beside it), its AOVs and
// the names of their ids.
std::vector<std::string> WriteFiles(const RenderedView& rendered, const Options& o) {
  const RenderedFrame& frame = rendered.frame;
  std::vector<std::string> files = WriteImageWithAovs(frame.denoised ? *frame.denoised : frame.image, rendered.aovs,
                                                      o.out, o.Display(), rendered.ids);
  if (frame.denoised) {
    files.push_back(SiblingPath(o.out, "raw"));
    WriteImage(frame.image, files.back(), o.Display());
  }
  return files;
}

}  // namespace

int Finish(const Options& o, Prepared& p, const RenderedView& rendered, const RenderedFrame* reference,
           std::string* frameStats) {
  const RenderedFrame& frame = rendered.frame;
  RunTimes& times = p.times();
  times.render = frame.seconds;
  times.aov = frame.aovSeconds;
  times.denoise = frame.denoiseSeconds;
  PhaseTimer phase;
  const std::vector<std::string> files = WriteFiles(rendered, o);
  phase.Lap(times.write);
  int status = reference ? CompareBackends(*reference, frame, o) : 0;
  PrintRenderReport(p.scene().Stats(), frame, o, files, rendered.denoiser);
  const uint32_t validationMessages = ValidationMessagesOf(p.scene());
  if (validationMessages) {
    std::fprintf(stderr, "vkpt: %u Vulkan validation message(s) were reported\n", validationMessages);
    status = 3;
  }
  if (const int sig = GracefulStop::Signal()) {
    std::fprintf(stderr, "vkpt: interrupted by %s: %s holds the %u spp rendered (%s%s)\n",
                 sig == SIGTERM ? "SIGTERM" : "SIGINT", o.out.c_str(), frame.spp,
                 frame.stoppedBy == StopReason::kSignal ? "stopped early" : "the render had finished",
                 o.api.render.denoise && !frame.denoised ? ", not denoised" : "");
    status = 128 + sig;
  }
  if (!o.stats.empty() || frameStats) {
    times.total = SecondsSince(p.start);
    const std::string json =
        StatsJson(o, {p.scene(), frame, reference, times, validationMessages, status, files, p.view.prepared.memory});
    if (frameStats) *frameStats = json;
    else WriteFileAtomically(o.stats, {reinterpret_cast<const uint8_t*>(json.data()), json.size()});
  }
  return status;
}

}  // namespace vkpt::internal

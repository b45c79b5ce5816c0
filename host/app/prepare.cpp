#include "app/prepare.h"

#include <cstdio>
#include <cstdlib>
#include <string>

#include "app/report.h"
#include "image/image.h"
#include "util/atomic_write.h"
#include "util/byte_size.h"

namespace vkpt::internal {
namespace {

// Warnings and notices to stderr, what was loaded to stdout with -v; nothing where
// another process reports.
EngineLog LogFor(const Options& o, bool report) {
  EngineLog log;
  if (!report) return log;
  log.warning = [](const std::string& line) { std::fprintf(stderr, "vkpt: warning: %s\n", line.c_str()); };
  log.notice = [](const std::string& line) { std::fprintf(stderr, "vkpt: %s\n", line.c_str()); };
  if (o.verbose) log.info = [](const std::string& line) { std::printf("%s\n", line.c_str()); };
  return log;
}

}  // namespace

void PrepareFrame(Prepared& p, const Options& o, bool report, uint32_t ranks) {
  p.view.renderer.reset();
  p.settings = ClientViewOf(o, LogFor(o, report), ranks);
  p.view = p.client->Begin(o, p.settings);
  if (report && o.verbose) {
    const PreparedFrame& frame = p.view.prepared;
    PrintLoadReport(p.scene(), CameraOf(p.view));
    if (!o.api.scene.environment.empty())
      std::printf("  environment: rotated %g° about +Y\n", o.api.render.environmentRotation.value_or(0.0f));
    std::printf("  memory: %s counted for the %u × %u image (%s)\n", FormatBytes(frame.memory).c_str(), frame.size.x,
                frame.size.y, DescribeParts(frame.parts).c_str());
  }
}

Prepared Prepare(const Options& o, bool report, uint32_t ranks) {
  Prepared p;
  CheckOutputPath(o.out);  // fail before a long render, not after
  if (!o.stats.empty()) CheckWritablePath(o.stats, "a stats");
  // lavapipe reads LP_NUM_THREADS when the device is created: --threads applies to it too.
  if (o.api.scene.threads && (o.api.scene.backend != vkpt::Backend::Cpu || o.compare))
    setenv("LP_NUM_THREADS", std::to_string(o.api.scene.threads).c_str(), 1);
  p.client = std::make_unique<SceneClient>(o, LogFor(o, report));
  PrepareFrame(p, o, report, ranks);
  return p;
}

}  // namespace vkpt::internal

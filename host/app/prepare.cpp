#include "app/prepare.h"

#include <cstdio>
#include <cstdlib>
#include <string>

#include "app/report.h"
#include "image/image.h"
#include "session/aov.h"
#include "util/atomic_write.h"
#include "util/byte_size.h"

namespace vkpt {
namespace {

glm::vec3 Vec3(const std::array<float, 3>& v) { return {v[0], v[1], v[2]}; }

std::optional<glm::vec3> Vec3(const std::optional<std::array<float, 3>>& v) {
  return v ? std::optional<glm::vec3>(Vec3(*v)) : std::nullopt;
}

SceneSettings SceneSettingsFrom(const Options& o) {
  SceneSettings s;
  s.path = o.scene;
  s.load = o.load;
  s.choice = SceneChoice{o.variant, o.animation, o.at.value_or(0.0)};  // the first frame's pose
  s.env = o.env;
  s.envIntensity = o.envIntensity;
  s.leafSize = o.leafSize;
  s.splits = o.splits;
  s.backend = o.backend;
  s.device = o.device;
  s.validation = o.validation;
  s.threads = o.threads;
  s.compare = o.compare;
  s.once = !o.frames;
  return s;
}

FrameRequest RequestFrom(const Options& o, const EngineLog& log, uint32_t ranks) {
  FrameRequest r;
  r.camera = {o.camera, std::nullopt, Vec3(o.lookFrom), Vec3(o.lookAt), Vec3(o.up), o.fov, o.orbit};
  PictureSettings& p = r.picture;
  p.width = o.width;
  p.height = o.height;
  p.seed = o.seed;
  p.spp = o.spp;
  p.maxDepth = o.maxDepth;
  p.rrDepth = o.rrDepth;
  p.textureLod = o.textureLod;
  p.background = Vec3(o.background);
  p.envRotation = o.envRotation;
  p.time = o.at.value_or(0.0);
  FrameShape& shape = r.shape;
  shape.compare = o.compare;
  shape.ranks = ranks;
  shape.aovPass = o.denoise || NeedsAovPass(o.aovs);
  shape.aovIds = WantsIds(o.aovs);
  shape.aovChannels = AovChannels(o.aovs);
  shape.denoise = o.denoise;
  shape.exrOutput = FormatFromPath(o.out) == ImageFormat::Exr;
  r.name = o.out;
  r.log = log;
  return r;
}

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
  p.frame = p.loaded->Prepare(RequestFrom(o, LogFor(o, report), ranks));
  if (report && o.verbose) {
    PrintLoadReport(p.scene(), p.rs(), p.frame.camera, p.frame.cameraIndex);
    if (!o.env.empty()) std::printf("  environment: rotated %g° about +Y\n", o.envRotation);
    std::printf("  memory: %s counted for the %u × %u image (%s)\n", FormatBytes(p.frame.memory).c_str(),
                p.frame.size.x, p.frame.size.y, DescribeParts(p.frame.parts).c_str());
  }
}

Prepared Prepare(const Options& o, bool report, uint32_t ranks) {
  Prepared p;
  CheckOutputPath(o.out);  // fail before a long render, not after
  if (!o.stats.empty()) CheckWritablePath(o.stats, "a stats");
  // lavapipe reads LP_NUM_THREADS when the device is created: --threads applies to it too.
  if (o.threads && (o.backend != Backend::Cpu || o.compare))
    setenv("LP_NUM_THREADS", std::to_string(o.threads).c_str(), 1);
  p.loaded = std::make_unique<LoadedScene>(SceneSettingsFrom(o), LogFor(o, report));
  PrepareFrame(p, o, report, ranks);
  return p;
}

}  // namespace vkpt

#include "app/scene_client.h"

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "app/report.h"
#include "image/image.h"
#include "session/aov.h"
#include "util/graceful_stop.h"
#include "vkpt/client.h"

namespace vkpt::internal {
namespace {

vkpt::SceneOptions SceneOptionsOf(const Options& o) {
  vkpt::SceneOptions s;
  s.backend = o.backend == Backend::Cpu      ? vkpt::Backend::Cpu
              : o.backend == Backend::Vulkan ? vkpt::Backend::Vulkan
                                             : vkpt::Backend::Auto;
  s.device = o.device;
  s.validation = o.validation;
  s.threads = o.threads;
  s.maxMemory = o.load.maxMemory;
  s.maxTexels = o.load.maxTextureTexels;
  s.allowExternalUris = o.load.allowExternalUris;
  s.variant = o.variant;
  s.animation = o.animation;
  s.environment = o.env;
  s.environmentIntensity = o.envIntensity;
  s.lightSampler = o.lightSampler == LightSampler::kTree    ? vkpt::LightSampler::Tree
                   : o.lightSampler == LightSampler::kPower ? vkpt::LightSampler::Power
                                                            : vkpt::LightSampler::Auto;
  return s;
}

ClientScene ClientSceneOf(const Options& o, const EngineLog& log) {
  return {o.leafSize, o.splits, o.compare, !o.frames, o.at.value_or(0.0), log};
}

vkpt::Camera CameraOf(const Options& o) {
  vkpt::Camera c;
  c.index = o.camera;
  c.lookFrom = o.lookFrom;
  c.lookAt = o.lookAt;
  c.up = o.up;
  c.fovDegrees = o.fov;
  c.orbitDegrees = o.orbit.value_or(0.0);
  return c;
}

vkpt::RenderOptions RenderOptionsOf(const Options& o) {
  vkpt::RenderOptions r;
  r.width = o.width;
  r.height = o.height;
  r.spp = o.spp;  // the bound, already raised by a time or noise target (options.cpp)
  r.seconds = o.time;
  r.noiseTarget = o.noiseTarget;
  r.adaptive = o.adaptive;
  r.seed = o.seed;
  r.maxDepth = o.maxDepth;
  r.rrDepth = o.rrDepth;
  r.chunkSpp = o.chunkSpp;
  r.batch = o.batch;
  r.time = o.at.value_or(0.0);
  r.background = o.background;
  r.environmentRotation = o.envRotation;
  r.textureLod = o.textureLod;
  for (Aov aov : o.aovs) r.aovs.emplace_back(AovName(aov));
  r.denoise = o.denoise;
  return r;
}

}  // namespace

ApiSettings ApiSettingsOf(const Options& o) { return {SceneOptionsOf(o), CameraOf(o), RenderOptionsOf(o)}; }

ClientView ClientViewOf(const Options& o, const EngineLog& log, uint32_t ranks) {
  ClientView v;
  v.name = o.out;
  v.ranks = ranks;
  v.exrOutput = FormatFromPath(o.out) == ImageFormat::Exr;
  v.checkpointSeconds = o.checkpoint;
  v.checkpointPath = o.out;
  v.display = o.Display();
  v.log = log;
  v.warning = [](const std::string& line) {
    EndProgressLine();
    std::fprintf(stderr, "vkpt: warning: %s\n", line.c_str());
  };
  // Flushed line by line: a script reading a pipe sees each pass as it ends.
  if (o.verbose)
    v.report = [](const std::string& line) {
      std::printf("  %s\n", line.c_str());
      std::fflush(stdout);
    };
  return v;
}

struct SceneClient::Impl {
  vkpt::Scene scene;
  vkpt::RenderOptions frame;  // the render options of the frame begun last
};

SceneClient::SceneClient(const Options& o, const EngineLog& log)
    : impl_(std::make_unique<Impl>(Impl{OpenScene(o.scene, SceneOptionsOf(o), ClientSceneOf(o, log)), {}})) {}

SceneClient::~SceneClient() = default;
SceneClient::SceneClient(SceneClient&&) noexcept = default;
SceneClient& SceneClient::operator=(SceneClient&&) noexcept = default;

LoadedScene& SceneClient::Engine() { return EngineOf(impl_->scene); }

BegunView SceneClient::Begin(const Options& o, const ClientView& client) {
  impl_->frame = RenderOptionsOf(o);
  impl_->frame.progress = ProgressLine();
  impl_->frame.cancel = GracefulStop::Arrived;
  return BeginView(impl_->scene, CameraOf(o), impl_->frame, client);
}

RenderedView SceneClient::Finish(BegunView& view, SampleSource& source, const ClientView& client) {
  RenderedView rendered = FinishView(impl_->scene, view, source, impl_->frame, client);
  EndProgressLine();
  return rendered;
}

}  // namespace vkpt::internal

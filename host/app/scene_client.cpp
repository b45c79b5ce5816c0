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

ClientScene ClientSceneOf(const Options& o, const EngineLog& log) {
  return {o.leafSize, o.splits, o.compare, !o.frames, o.api.render.time.value_or(0.0), log};
}

}  // namespace

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
    : impl_(std::make_unique<Impl>(Impl{OpenScene(o.scene, o.api.scene, ClientSceneOf(o, log)), {}})) {}

SceneClient::~SceneClient() = default;
SceneClient::SceneClient(SceneClient&&) noexcept = default;
SceneClient& SceneClient::operator=(SceneClient&&) noexcept = default;

vkpt::Scene& SceneClient::Public() { return impl_->scene; }

BegunView SceneClient::Begin(const Options& o, const ClientView& client) {
  const ApiSettings& settings = o.api;
  impl_->frame = settings.render;
  impl_->frame.progress = ProgressLine();
  impl_->frame.cancel = GracefulStop::Arrived;
  return BeginView(impl_->scene, settings.camera, impl_->frame, client);
}

RenderedView SceneClient::Finish(BegunView& view, SampleSource& source, const ClientView& client) {
  RenderedView rendered = FinishView(impl_->scene, view, source, impl_->frame, client);
  EndProgressLine();
  return rendered;
}

}  // namespace vkpt::internal

// A Scene on the engine: the public options mapped onto the engine's settings
// (engine/settings.h), and a view's render as the library and the command line run it.
#include <memory>
#include <utility>

#include <glm/gtc/type_ptr.hpp>

#include "session/aov.h"
#include "session/budget.h"
#include "session/local_passes.h"
#include "vkpt/caller_log.h"
#include "vkpt/client.h"
#include "vkpt/scene_access.h"
#include "vkpt/scene_records.h"

namespace vkpt::internal {
namespace {

SceneSettings ToSettings(const std::string& path, const vkpt::SceneOptions& o, const ClientScene& client) {
  SceneSettings s;
  using InternalBackend = decltype(s.backend);
  s.path = path;
  s.load.maxMemory = o.maxMemory;
  s.load.maxTextureTexels = o.maxTexels;
  s.load.allowExternalUris = o.allowExternalUris;
  s.choice.variant = o.variant;
  s.choice.animation = o.animation;
  s.choice.time = client.time;
  s.env = o.environment;
  s.envIntensity = o.environmentIntensity;
  using InternalSampler = decltype(s.lightSampler);
  s.lightSampler = o.lightSampler == vkpt::LightSampler::Tree    ? InternalSampler::kTree
                   : o.lightSampler == vkpt::LightSampler::Power ? InternalSampler::kPower
                                                                 : InternalSampler::kAuto;
  s.backend = o.backend == vkpt::Backend::Cpu      ? InternalBackend::Cpu
              : o.backend == vkpt::Backend::Vulkan ? InternalBackend::Vulkan
                                                   : InternalBackend::Auto;
  s.device = o.device;
  s.validation = o.validation;
  s.threads = o.threads;
  s.leafSize = client.leafSize;
  s.splits = client.splits;
  s.compare = client.compare;
  s.once = client.once;
  return s;
}

RenderBudget ToBudget(const vkpt::RenderOptions& o, const ClientView& client) {
  return BudgetFor({o.spp, o.seconds, o.noiseTarget, o.adaptive, client.checkpointSeconds, o.chunkSpp});
}

std::optional<glm::vec3> ToVec3(const std::optional<std::array<float, 3>>& v) {
  return v ? std::optional<glm::vec3>(glm::vec3((*v)[0], (*v)[1], (*v)[2])) : std::nullopt;
}

FrameRequest ToRequest(const vkpt::Camera& c, const vkpt::RenderOptions& o, const std::vector<Aov>& aovs,
                       const ClientView& client, bool compare) {
  FrameRequest r;
  CameraSettings& camera = r.camera;
  camera.index = c.index;
  if (c.matrix) camera.matrix = glm::make_mat4(c.matrix->data());
  camera.lookFrom = ToVec3(c.lookFrom);
  camera.lookAt = ToVec3(c.lookAt);
  camera.up = ToVec3(c.up);
  camera.fov = c.fovDegrees;
  if (c.orbitDegrees != 0.0) camera.orbit = c.orbitDegrees;
  PictureSettings& p = r.picture;
  p.width = o.width;
  p.height = o.height;
  p.seed = o.seed;
  p.maxDepth = o.maxDepth;
  p.rrDepth = o.rrDepth;
  p.textureLod = o.textureLod;
  p.background = ToVec3(o.background);
  p.envRotation = o.environmentRotation;
  p.time = o.time;
  FrameShape& shape = r.shape;
  shape.compare = compare;
  shape.ranks = client.ranks;
  shape.aovPass = o.denoise || NeedsAovPass(aovs);
  shape.aovIds = WantsIds(aovs);
  shape.aovChannels = AovChannels(aovs);
  shape.denoise = o.denoise;
  shape.exrOutput = client.exrOutput;
  r.name = client.name;
  r.log = client.log;
  return r;
}

}  // namespace

vkpt::Scene OpenScene(const std::string& path, const vkpt::SceneOptions& options, const ClientScene& client) {
  CheckSettings({options, {}, {}});
  return vkpt::SceneAccess::Make(std::make_unique<LoadedScene>(ToSettings(path, options, client), client.log), options);
}

namespace {
LoadedScene& EngineOf(vkpt::Scene& scene) { return vkpt::SceneAccess::Engine(scene); }
}  // namespace

RunTimes& TimesOf(vkpt::Scene& scene) { return EngineOf(scene).times; }

uint32_t ValidationMessagesOf(const vkpt::Scene& scene) {
  const vk::Context* device = vkpt::SceneAccess::Engine(scene).Device();
  return device ? device->ValidationMessages() : 0;
}

BegunView BeginView(vkpt::Scene& scene, const vkpt::Camera& camera, const vkpt::RenderOptions& options,
                    const ClientView& client) {
  CheckSettings({vkpt::SceneAccess::Options(scene), camera, options});
  vkpt::SceneAccess::EndProgressive(scene);  // its device frame released before the next is made
  LoadedScene& loaded = EngineOf(scene);
  BegunView view;
  view.aovs = AovsFromNames(options.aovs);
  view.prepared = loaded.Prepare(ToRequest(camera, options, view.aovs, client, loaded.Settings().compare));
  view.renderer = loaded.BeginFrame(view.prepared.params, options.batch);
  return view;
}

SessionSettings SessionOf(LoadedScene& loaded, const BegunView& view, const vkpt::RenderOptions& options,
                          const ClientView& client) {
  SessionSettings settings;
  settings.budget = ToBudget(options, client);
  settings.checkpointPath = client.checkpointPath;
  settings.display = client.display;
  settings.aovPass = NeedsAovPass(view.aovs);
  settings.aovIds = WantsIds(view.aovs);
  settings.stop = options.cancel;
  if (options.denoise) settings.denoise = loaded.Backend().MakeDenoiser();
  return settings;
}

RenderedView Resolved(LoadedScene& loaded, const BegunView& view, RenderedFrame frame) {
  RenderedView rendered;
  rendered.frame = std::move(frame);
  const RenderedFrame& f = rendered.frame;
  rendered.aovs = ResolveAovs(view.aovs, f.aovs, f.sums, f.image, loaded.IdsOf());
  if (WantsIds(view.aovs)) rendered.ids = loaded.IdsJson();
  rendered.denoiser = loaded.Backend().DenoiserName();
  return rendered;
}

RenderedView FinishView(vkpt::Scene& scene, BegunView& view, SampleSource& source, const vkpt::RenderOptions& options,
                        const ClientView& client) {
  LoadedScene& loaded = EngineOf(scene);
  const SessionHooks hooks{options.progress, client.report, client.warning};
  return Resolved(loaded, view, RenderSession(source, SessionOf(loaded, view, options, client), hooks));
}

vkpt::CameraInfo CameraOf(const BegunView& view) {
  return CameraInfoOf(view.prepared.camera, view.prepared.cameraIndex);
}

RenderedFrame RenderOnCpu(vkpt::Scene& scene, const BegunView& view, const SessionSettings& settings,
                          const SessionHooks& hooks) {
  LoadedScene& loaded = EngineOf(scene);
  const RenderBackend cpu(nullptr, loaded.Arrays(), loaded.Settings().threads);
  const std::unique_ptr<FrameRenderer> frame = cpu.BeginFrame(view.prepared.params, 0);
  LocalPasses source(*frame, settings.budget.chunkSpp);
  return RenderSession(source, settings, hooks);
}

}  // namespace vkpt::internal

namespace vkpt {

Scene::Scene(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

Scene::Scene(const std::string& path, const SceneOptions& options)
    : Scene(internal::Translated([&] {
        internal::ClientScene client;
        client.log = internal::EngineLogOf(options.log);
        return std::move(internal::OpenScene(path, options, client).impl_);
      })) {
  internal::LogLoad(options.log, SceneAccess::Engine(*this).scene());
}

Scene::~Scene() = default;
Scene::Scene(Scene&&) noexcept = default;
Scene& Scene::operator=(Scene&&) noexcept = default;

uint32_t Scene::CameraCount() const { return uint32_t(SceneAccess::Engine(*this).scene().cameras.size()); }

std::string Scene::Device() const {
  const internal::vk::Context* device = SceneAccess::Engine(*this).Device();
  return device ? std::string(device->Properties().deviceName) : "cpu";
}

}  // namespace vkpt

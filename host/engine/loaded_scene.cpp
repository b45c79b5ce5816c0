#include "engine/loaded_scene.h"

#include <cstdio>

#include "engine/camera_choice.h"
#include "engine/environment_load.h"
#include "render/light_table.h"
#include "render/studio_environment.h"
#include "scene/load_limits.h"
#include "scene/scene_ids.h"
#include "shared/sampling.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

// The Vulkan context the settings ask for: required for Backend::Vulkan, a named device,
// validation or a comparison; for Backend::Auto a device that does not open leaves the
// CPU to render, with a notice saying why.
std::unique_ptr<vk::Context> OpenDevice(const SceneSettings& s, const EngineLog& log) {
  if (s.backend == Backend::Cpu && !s.compare) return nullptr;
  vk::ContextOptions opt;
  opt.validation = s.validation;
  opt.device = s.device;
  if (s.backend == Backend::Vulkan || s.compare || !s.device.empty() || s.validation)
    return std::make_unique<vk::Context>(opt);
  try {
    return std::make_unique<vk::Context>(opt);
  } catch (const Error& e) {
    log.Notice(std::string(e.what()) + "\nvkpt: rendering on the CPU instead");
    return nullptr;
  }
}

// The environment map joins the light table, last; then the light sampler is chosen.
void CompleteLightTable(RenderScene& rs, const SceneSettings& s) {
  if (rs.environment.width > 0) AddEnvironmentLight(rs, s.envIntensity);
  ChooseLightSampler(rs, s.lightSampler);
}

// The BVH and the renderers' arrays, with the environment map. `gpu`: a Vulkan device will
// render, so the shader's layout of the tree is built, in direction-ordered copies; the
// CPU's layout only where the CPU renders (no device, or a comparison).
// With `studio`, a scene without light sources is lit by the studio environment.
RenderScene BuildArrays(const Scene& scene, const SceneSettings& s, bool gpu, EnvironmentMap env, bool studio) {
  BvhBuildOptions bvhOptions;
  bvhOptions.maxLeafSize = s.leafSize;
  bvhOptions.splits = s.splits;
  bvhOptions.threads = s.threads;
  bvhOptions.directionCopies = gpu;
  RenderScene rs = PrepareRenderScene(scene, bvhOptions, !gpu || s.compare, gpu);
  rs.environment = studio && !HasLightSources(rs) ? StudioEnvironment() : std::move(env);
  CompleteLightTable(rs, s);
  return rs;
}

}  // namespace

LoadedScene::LoadedScene(const SceneSettings& settings, const EngineLog& log) : settings_(settings), log_(log) {
  PhaseTimer phase;
  asset_ = std::make_unique<GltfAsset>(settings_.path, settings_.load, settings_.choice);
  phase.Lap(times.load);
  // Posed at once, at the time the caller expects to render first, so that the scene's
  // cameras and bounds are known (and its faults reported) before a render.
  posedAt_ = settings_.choice.time;
  asset_->PoseAt(posedAt_);
  phase.Lap(times.pose);
  environment_ = LoadEnvironment(settings_, scene(), log_, &environmentBytes_);
  phase.Lap(times.environment);
  // The device before the scene's arrays: without one (Backend::Auto) the CPU renders,
  // and only then does the scene need the CPU's BVH layout.
  ctx_ = OpenDevice(settings_, log_);
}

LoadedScene::~LoadedScene() = default;

PreparedFrame LoadedScene::Prepare(const FrameRequest& request) {
  PhaseTimer phase;
  // Without an animation every pose is the same: the first one's arrays serve every render.
  const bool animated = scene().animation >= 0;
  const double time = request.picture.time.value_or(settings_.choice.time);
  if (animated && posedAt_ != time) {
    asset_->PoseAt(time);
    posedAt_ = time;
    phase.Lap(times.pose);
  }
  // A request refused here (its camera, its memory) leaves the scene as it was.
  PreparedFrame frame;
  frame.cameraIndex = request.camera.index.value_or(0);
  frame.camera = ChooseCamera(scene(), request.camera, settings_.path);
  frame.size = ImageSize(frame.camera, request.picture, settings_.path);
  if (request.shape.aovIds) CheckIdsAreExact(IdCountsOf(scene()), settings_.path);
  ChargeFrame(frame, request);
  if (settings_.once) asset_->ReleaseSource();  // no other pose will be asked for
  phase.Restart();
  // Without a map or a background, a scene without light sources is lit by the studio:
  // the arrays are built again where that choice changes (a background given to one
  // render and not to the next, or an edit that makes the first light or removes the last).
  const bool studio = settings_.env.empty() && !request.picture.background;
  bool build = !builtAt_ || *builtAt_ != posedAt_ || (studio != studioAllowed_ && !HasLightSources(rs_));
  std::vector<uint32_t> lightsBefore;
  if (!build && restyle_) {
    lightsBefore = TriangleLights(rs_);
    RestyleRenderScene(scene(), rs_);
    build = (studio && !HasLightSources(rs_)) != studioLit_;
  }
  if (build) {
    backend_.reset();  // the last pose's device buffers and arrays go before the next's are made
    rs_ = RenderScene{};
    builtAt_.reset();
    // One render hands the map over; any other keeps it for the renders after a failure
    // or a new pose.
    rs_ = BuildArrays(scene(), settings_, ctx_ != nullptr, settings_.once ? std::move(environment_) : environment_,
                      studio);
    studioAllowed_ = studio;
    studioLit_ = studio && !HasLightSources(rs_);
    builtAt_ = posedAt_;
    restyle_ = false;
    ++counts_.builds;
  } else if (restyle_) {
    CompleteLightTable(rs_, settings_);
    if (backend_) backend_->Restyle(TriangleLights(rs_) != lightsBefore);
    restyle_ = false;
    ++counts_.restyles;
  }
  phase.Lap(times.prepare);
  frame.params = FrameParams(frame.camera, frame.size, request.picture, request.log);
  return frame;
}

void LoadedScene::Edit(const AssetEdits& edits, double time) {
  if (!edits.Empty()) {
    if (asset_->Edit(edits, time)) builtAt_.reset();
    else restyle_ = true;
    posedAt_ = scene().animationTime;
  }
  settings_.choice.time = time;
}

void LoadedScene::SetEnvironment(float intensity, float rotation) {
  if (intensity != settings_.envIntensity) restyle_ = true;
  settings_.envIntensity = intensity;
  settings_.envRotation = rotation;
}

const RenderBackend& LoadedScene::Backend() {
  if (!backend_) {
    backend_ = std::make_unique<RenderBackend>(ctx_.get(), rs_, settings_.threads);
    if (ctx_) ++counts_.uploads;
  }
  return *backend_;
}

TriangleIdsOf LoadedScene::IdsOf() const {
  return [&scene = scene()](uint32_t triangle) {
    const TriangleIds ids = IdsOfTriangle(scene, triangle);
    return std::array<int64_t, 3>{ids.object, ids.material, ids.instance};
  };
}

std::string LoadedScene::IdsJson() const { return vkpt::internal::IdsJson(scene()); }

std::unique_ptr<FrameRenderer> LoadedScene::BeginFrame(const shader::FrameParams& params, uint32_t batch) {
  PhaseTimer phase;
  std::unique_ptr<FrameRenderer> frame = Backend().BeginFrame(params, batch);
  if (ctx_) phase.Lap(times.upload);
  return frame;
}

// A scene without light sources (HasLightSources) is lit by the studio environment
// (render/studio_environment.h) unless a map or a background says otherwise, and a black
// background is warned about.
shader::FrameParams LoadedScene::FrameParams(const Camera& cam, glm::uvec2 size, const PictureSettings& p,
                                             const EngineLog& log) const {
  shader::FrameParams params = MakeFrameParams(rs_, cam, size.x, size.y);
  params.seed = p.seed;
  params.sampleBegin = 0;
  params.sampleCount = 0;  // each pass of a render sets its own (FrameRenderer::AddSamples)
  params.maxDepth = p.maxDepth;
  params.rrDepth = p.rrDepth;
  params.textureLod = p.textureLod ? 1u : 0u;
  if (!settings_.env.empty()) {
    SetEnvironmentParams(params, rs_.environment, p.envRotation.value_or(settings_.envRotation),
                         settings_.envIntensity);
  } else if (p.background) {
    params.background = *p.background;
  } else if (studioLit_) {
    SetEnvironmentParams(params, rs_.environment, 0.0f, 1.0f);
    log.Info(std::string("  no lights") + (rs_.lights.size() == 1 ? "" : " but emissive textures") +
             ": lit by the studio environment (--background 1: a uniform white one)");
  }
  if (rs_.lights.empty() && settings_.env.empty() && shader::MaxComponent(params.background) <= 0.0f)
    log.Warn(settings_.path + ": no lights and a black background; the image will be black");
  return params;
}

// The frame's memory (session/frame_memory.h) on top of the scene's and the map's, against
// the scene's memory limit, before the device or the film allocates any of it.
void LoadedScene::ChargeFrame(PreparedFrame& frame, const FrameRequest& request) const {
  FrameShape shape = request.shape;
  shape.width = frame.size.x;
  shape.height = frame.size.y;
  shape.gpu = ctx_ != nullptr;
  // A discrete GPU's buffers are its own; any other device's live in this process's memory.
  shape.deviceInHost = !ctx_ || ctx_->Properties().deviceType != VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU;
  frame.parts = FrameMemoryParts(shape);
  frame.memory = BytesPerPixel(frame.parts) * shape.width * shape.height;
  // A map kept for later renders is counted twice while the arrays hold the other copy.
  const bool keepMap = !settings_.once;
  MemoryBudget budget(scene().memoryLimit, request.name.empty() ? settings_.path : request.name);
  budget.Charge(scene().memoryCounted + environmentBytes_ * (keepMap ? 2 : 1), "the scene and environment");
  budget.Charge(frame.memory,
                "a " + std::to_string(shape.width) + " × " + std::to_string(shape.height) + " image (" +
                    DescribeParts(frame.parts) + ")",
                "lower --width and --height, or raise --max-memory");
}

}  // namespace vkpt::internal

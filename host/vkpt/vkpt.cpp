// The library's facade: the public types of vkpt/vkpt.h mapped onto the engine's
// (engine/loaded_scene.h), so that a Scene renders exactly what the command line renders.
//
// The internal headers come first and on their own: their types (vkpt::Scene, vkpt::Image,
// vkpt::Backend) share names with the public ones of vkpt::api, so each internal header is
// read before those exist, and below the public types are named api::… and the internal
// ones only through the engine's structs.
#include <exception>
#include <new>
#include <utility>

#include <glm/gtc/type_ptr.hpp>

#include "engine/loaded_scene.h"
#include "image/image.h"
#include "image/view_transform.h"
#include "session/aov.h"
#include "session/budget.h"
#include "session/local_passes.h"
#include "session/render_session.h"
#include "vkpt/api_terms.h"

namespace vkpt {
using InternalImage = Image;  // vkpt::Image is ambiguous once api::Image exists
}  // namespace vkpt

#include "vkpt/vkpt.h"

namespace vkpt {
namespace {

SceneSettings ToSettings(const std::string& path, const api::SceneOptions& o) {
  SceneSettings s;
  using InternalBackend = decltype(s.backend);
  s.path = path;
  s.load.maxMemory = o.maxMemory;
  s.load.maxTextureTexels = o.maxTexels;
  s.load.allowExternalUris = o.allowExternalUris;
  s.choice.variant = o.variant;
  s.choice.animation = o.animation;
  s.env = o.environment;
  s.envIntensity = o.environmentIntensity;
  s.backend = o.backend == api::Backend::Cpu      ? InternalBackend::Cpu
              : o.backend == api::Backend::Vulkan ? InternalBackend::Vulkan
                                                  : InternalBackend::Auto;
  s.device = o.device;
  s.validation = o.validation;
  s.threads = o.threads;
  return s;
}

RenderBudget ToBudget(const api::RenderOptions& o) {
  return BudgetFor({o.spp, o.seconds, o.noiseTarget, o.adaptive, 0.0, o.chunkSpp});
}

FrameRequest ToRequest(const api::Camera& c, const api::RenderOptions& o, const std::vector<Aov>& aovs) {
  auto vec3 = [](const std::optional<std::array<float, 3>>& v) {
    return v ? std::optional<glm::vec3>(glm::vec3((*v)[0], (*v)[1], (*v)[2])) : std::nullopt;
  };
  FrameRequest r;
  CameraSettings& camera = r.camera;
  camera.index = c.index;
  if (c.matrix) camera.matrix = glm::make_mat4(c.matrix->data());
  camera.lookFrom = vec3(c.lookFrom);
  camera.lookAt = vec3(c.lookAt);
  camera.up = vec3(c.up);
  camera.fov = c.fovDegrees;
  if (c.orbitDegrees != 0.0) camera.orbit = c.orbitDegrees;
  PictureSettings& p = r.picture;
  p.width = o.width;
  p.height = o.height;
  p.seed = o.seed;
  p.spp = ToBudget(o).maxSpp;
  p.maxDepth = o.maxDepth;
  p.rrDepth = o.rrDepth;
  p.textureLod = o.textureLod;
  p.background = vec3(o.background);
  p.envRotation = o.environmentRotation;
  p.time = o.time;
  r.shape.aovPass = o.denoise || NeedsAovPass(aovs);
  r.shape.aovIds = WantsIds(aovs);
  r.shape.aovChannels = AovChannels(aovs);
  r.shape.denoise = o.denoise;
  return r;
}

api::Image ToImage(const std::vector<glm::vec3>& pixels, uint32_t width, uint32_t height) {
  api::Image image{width, height, 3, {"R", "G", "B"}, {}};
  image.data.reserve(pixels.size() * 3);
  for (const glm::vec3& p : pixels) image.data.insert(image.data.end(), {p.r, p.g, p.b});
  return image;
}

// The internal image of a public one's RGB values (no variance: files do not hold it).
InternalImage ToInternal(const api::Image& image) {
  if (image.channels != 3 || image.data.size() != size_t(image.width) * image.height * 3)
    throw api::Error("an image to save needs 3 channels of width × height values");
  InternalImage internal(image.width, image.height);
  for (size_t i = 0; i < internal.pixels.size(); ++i)
    internal.pixels[i] = glm::vec3(image.data[3 * i], image.data[3 * i + 1], image.data[3 * i + 2]);
  return internal;
}

AovLayer ToLayer(const std::string& name, const api::Image& aov, const api::Image& image) {
  const std::optional<Aov> known = AovFromName(name);
  if (!known) throw api::Error("cannot save an AOV named \"" + name + "\"");
  if (aov.width != image.width || aov.height != image.height || aov.channelNames.size() != aov.channels ||
      aov.data.size() != size_t(aov.width) * aov.height * aov.channels)
    throw api::Error("AOV \"" + name + "\" does not match the image's size");
  return {*known, aov.channelNames, aov.data};
}

// Any failure inside as the one public exception, its message in the API's terms.
template <class F>
auto Translated(F&& f) {
  try {
    return f();
  } catch (const api::Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw api::Error("out of memory");
  } catch (const std::exception& e) {
    throw api::Error(InApiTerms(e.what()));
  }
}

}  // namespace

struct api::Scene::Impl {
  std::unique_ptr<LoadedScene> loaded;
};

api::Scene::Scene(const std::string& path, const SceneOptions& options)
    : impl_(Translated([&] {
        return std::make_unique<Impl>(Impl{std::make_unique<LoadedScene>(ToSettings(path, options), EngineLog{})});
      })) {}

api::Scene::~Scene() = default;
api::Scene::Scene(Scene&&) noexcept = default;
api::Scene& api::Scene::operator=(Scene&&) noexcept = default;

uint32_t api::Scene::CameraCount() const { return uint32_t(impl_->loaded->scene().cameras.size()); }

std::string api::Scene::Device() const {
  const vk::Context* device = impl_->loaded->Device();
  return device ? std::string(device->Properties().deviceName) : "cpu";
}

api::RenderResult api::Scene::Render(const Camera& camera, const RenderOptions& options) {
  return Translated([&] {
    LoadedScene& loaded = *impl_->loaded;
    const std::vector<Aov> aovs = AovsFromNames(options.aovs);
    const PreparedFrame frame = loaded.Prepare(ToRequest(camera, options, aovs));
    const std::unique_ptr<FrameRenderer> renderer = loaded.BeginFrame(frame.params, options.batch);
    LocalPasses source(*renderer, options.chunkSpp);
    SessionSettings settings;
    settings.budget = ToBudget(options);
    settings.aovPass = NeedsAovPass(aovs);
    settings.aovIds = WantsIds(aovs);
    settings.stop = options.cancel;
    if (options.denoise) settings.denoise = loaded.Backend().MakeDenoiser();
    SessionHooks hooks;
    hooks.progress = options.progress;
    const RenderedFrame rendered = RenderSession(source, settings, hooks);

    RenderResult result;
    const uint32_t w = frame.size.x, h = frame.size.y;
    result.image = ToImage(rendered.denoised ? rendered.denoised->pixels : rendered.image.pixels, w, h);
    if (rendered.denoised) result.raw = ToImage(rendered.image.pixels, w, h);
    for (AovLayer& layer : ResolveAovs(aovs, rendered.aovs, rendered.sums, rendered.image, loaded.IdsOf())) {
      const uint32_t channels = uint32_t(layer.suffixes.size());
      result.aovs[AovName(layer.aov)] = {w, h, channels, std::move(layer.suffixes), std::move(layer.values)};
    }
    if (WantsIds(aovs)) result.ids = loaded.IdsJson();
    result.spp = rendered.spp;
    result.samples = rendered.samples;
    result.stoppedBy = rendered.stoppedBy == StopReason::kSignal ? "cancelled" : StopReasonName(rendered.stoppedBy);
    result.estimatedRelMse = rendered.estimatedRelMse;
    result.seconds = rendered.seconds + rendered.aovSeconds + rendered.denoiseSeconds;
    result.engine = rendered.engine;
    return result;
  });
}

std::vector<std::string> api::Save(const RenderResult& result, const std::string& path, const std::string& view,
                                   float exposure) {
  return Translated([&] {
    const std::optional<View> known = ViewFromName(view);
    if (!known) throw api::Error("unknown view \"" + view + "\" (neutral, agx, aces or clamp)");
    const DisplayTransform display{*known, exposure};
    std::vector<AovLayer> layers;
    for (const auto& [name, aov] : result.aovs) layers.push_back(ToLayer(name, aov, result.image));
    std::vector<std::string> files = WriteImageWithAovs(ToInternal(result.image), layers, path, display, result.ids);
    if (result.raw) {
      files.push_back(SiblingPath(path, "raw"));
      WriteImage(ToInternal(*result.raw), files.back(), display);
    }
    return files;
  });
}

}  // namespace vkpt

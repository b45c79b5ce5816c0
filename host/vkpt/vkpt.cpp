// The library's facade: a Scene's render (vkpt/client.h's view, as the command line
// renders it) given back in the public types of vkpt/vkpt.h, and Save.
//
// The internal headers come first and on their own: their types (vkpt::Scene, vkpt::Image,
// vkpt::Backend) share names with the public ones of vkpt::api, so each internal header is
// read before those exist, and below the public types are named api::… and the internal
// ones only through the engine's structs.
#include <utility>

#include "image/image.h"
#include "image/view_transform.h"
#include "session/aov.h"
#include "session/local_passes.h"

namespace vkpt {
using InternalImage = Image;  // vkpt::Image is ambiguous once api::Image exists
}  // namespace vkpt

#include "vkpt/client.h"

namespace vkpt {
namespace {

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

}  // namespace

api::RenderResult api::Scene::Render(const Camera& camera, const RenderOptions& options) {
  return Translated([&] {
    BegunView view = BeginView(*this, camera, options, {});
    LocalPasses source(*view.renderer, options.chunkSpp);
    RenderedView rendered = FinishView(*this, view, source, options, {});
    const RenderedFrame& frame = rendered.frame;
    RenderResult result;
    const uint32_t w = view.prepared.size.x, h = view.prepared.size.y;
    result.image = ToImage(frame.denoised ? frame.denoised->pixels : frame.image.pixels, w, h);
    if (frame.denoised) result.raw = ToImage(frame.image.pixels, w, h);
    for (AovLayer& layer : rendered.aovs) {
      const uint32_t channels = uint32_t(layer.suffixes.size());
      result.aovs[AovName(layer.aov)] = {w, h, channels, std::move(layer.suffixes), std::move(layer.values)};
    }
    result.ids = std::move(rendered.ids);
    result.spp = frame.spp;
    result.samples = frame.samples;
    result.stoppedBy = frame.stoppedBy == StopReason::kSignal ? "cancelled" : StopReasonName(frame.stoppedBy);
    result.estimatedRelMse = frame.estimatedRelMse;
    result.seconds = frame.seconds + frame.aovSeconds + frame.denoiseSeconds;
    result.engine = frame.engine;
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

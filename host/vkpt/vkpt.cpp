// The library's facade: a Scene's render (vkpt/client.h's view, as the command line
// renders it) given back in the public types of vkpt/vkpt.h, Save and Devices. Below, vkpt::Image
// is the public image and Image the engine's (vkpt::internal).
#include <utility>

#include "engine/devices.h"
#include "image/aov_files.h"
#include "image/image.h"
#include "image/view_transform.h"
#include "session/aov.h"
#include "session/local_passes.h"
#include "vkpt/caller_log.h"
#include "vkpt/client.h"
#include "vkpt/public_result.h"
#include "vkpt/scene_access.h"

namespace vkpt::internal {
namespace {

// The internal image of a public one's RGB values (no variance: files do not hold it).
Image ToInternal(const vkpt::Image& image) {
  if (image.channels != 3 || image.data.size() != size_t(image.width) * image.height * 3)
    throw vkpt::Error("an image to save needs 3 channels of width × height values");
  Image internal(image.width, image.height);
  for (size_t i = 0; i < internal.pixels.size(); ++i)
    internal.pixels[i] = glm::vec3(image.data[3 * i], image.data[3 * i + 1], image.data[3 * i + 2]);
  return internal;
}

AovLayer ToLayer(const std::string& name, const vkpt::Image& aov, const vkpt::Image& image) {
  const std::optional<Aov> known = AovFromName(name);
  if (!known) throw vkpt::Error("cannot save an AOV named \"" + name + "\"");
  if (aov.width != image.width || aov.height != image.height || aov.channelNames.size() != aov.channels ||
      aov.data.size() != size_t(aov.width) * aov.height * aov.channels)
    throw vkpt::Error("AOV \"" + name + "\" does not match the image's size");
  return {*known, aov.channelNames, aov.data};
}

vkpt::RenderResult RenderView(vkpt::Scene& scene, const vkpt::Camera& camera, const vkpt::RenderOptions& options) {
  return Translated([&] {
    const vkpt::LogCallback& log = vkpt::SceneAccess::Options(scene).log;
    const ClientView client = LoggedView(log);
    const uint32_t validationBefore = ValidationMessagesOf(scene);
    BegunView view = BeginView(scene, camera, options, client);
    LocalPasses source(*view.renderer, options.chunkSpp);
    RenderedView rendered = FinishView(scene, view, source, options, client);
    if (const uint32_t validation = ValidationMessagesOf(scene) - validationBefore; validation && log)
      log(vkpt::LogLevel::Warning, std::to_string(validation) + " Vulkan validation message(s) in this render");
    return PublicResult(view, rendered);
  });
}

std::vector<std::string> SaveRender(const vkpt::RenderResult& result, const std::string& path, const std::string& view,
                                    float exposure) {
  return Translated([&] {
    const std::optional<View> known = ViewFromName(view);
    if (!known) throw vkpt::Error("unknown view \"" + view + "\" (neutral, agx, aces or clamp)");
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

}  // namespace
}  // namespace vkpt::internal

namespace vkpt {

RenderResult Scene::Render(const Camera& camera, const RenderOptions& options) {
  return internal::RenderView(*this, camera, options);
}

std::vector<std::string> v1::Save(const RenderResult& result, const std::string& path, const std::string& view,
                                  float exposure) {
  return internal::SaveRender(result, path, view, exposure);
}

std::vector<Device> v1::Devices() {
  return internal::Translated([] {
    std::vector<Device> devices;
    for (const internal::DeviceDescription& d : internal::DescribeDevices())
      devices.push_back({d.index, d.name, d.type, d.apiMajor, d.apiMinor, d.compute});
    return devices;
  });
}

}  // namespace vkpt

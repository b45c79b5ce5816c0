#include "vkpt/public_result.h"

#include <utility>
#include <vector>

#include "session/aov.h"

namespace vkpt::internal {
namespace {

vkpt::Image ToImage(const std::vector<glm::vec3>& pixels, uint32_t width, uint32_t height) {
  vkpt::Image image{width, height, 3, {"R", "G", "B"}, {}};
  image.data.reserve(pixels.size() * 3);
  for (const glm::vec3& p : pixels) image.data.insert(image.data.end(), {p.r, p.g, p.b});
  return image;
}

}  // namespace

std::string PublicStopReason(StopReason reason) {
  return reason == StopReason::kSignal ? "cancelled" : StopReasonName(reason);
}

vkpt::RenderResult PublicResult(const BegunView& view, RenderedView& rendered) {
  const RenderedFrame& frame = rendered.frame;
  vkpt::RenderResult result;
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
  result.stoppedBy = PublicStopReason(frame.stoppedBy);
  result.estimatedRelMse = frame.estimatedRelMse;
  result.seconds = frame.seconds + frame.aovSeconds + frame.denoiseSeconds;
  result.engine = frame.engine;
  return result;
}

}  // namespace vkpt::internal

#include "viewer/display_pixels.h"

#include "image/image.h"

namespace vkpt::internal {

std::vector<uint8_t> DisplayPixels(const vkpt::Image& image, const DisplayTransform& display) {
  const size_t pixels = size_t(image.width) * image.height;
  std::vector<uint8_t> rgba(pixels * 4, 255);
  for (size_t i = 0; i < pixels; ++i) {
    const float* rgb = &image.data[i * image.channels];
    const glm::vec3 shown = display.Apply(glm::vec3(rgb[0], rgb[1], rgb[2]));
    for (int c = 0; c < 3; ++c) rgba[i * 4 + c] = LinearToSrgb8(shown[c]);
  }
  return rgba;
}

}  // namespace vkpt::internal

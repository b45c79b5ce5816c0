#include "viewer/display_pixels.h"

#include <algorithm>
#include <cmath>

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

std::vector<uint8_t> DisplayAov(const vkpt::Image& aov, const std::string& name) {
  const size_t pixels = size_t(aov.width) * aov.height;
  std::vector<uint8_t> rgba(pixels * 4, 255);
  float farthest = 0.0f;
  if (name == "depth")
    for (float z : aov.data) farthest = std::max(farthest, std::isfinite(z) ? z : 0.0f);
  for (size_t i = 0; i < pixels; ++i) {
    const float* v = &aov.data[i * aov.channels];
    glm::vec3 shown(0.0f);
    if (name == "normal") {
      shown = 0.5f * glm::vec3(v[0], v[1], v[2]) + 0.5f;
    } else if (name == "depth") {
      shown = glm::vec3(v[0] > 0.0f && farthest > 0.0f ? 1.0f - 0.9f * v[0] / farthest : 0.0f);
    } else if (aov.channels == 1) {  // an id: a hash of it as a hue, fully bright
      if (v[0] >= 0.0f) {
        uint32_t h = uint32_t(v[0]) * 2654435761u;
        shown = glm::vec3((h >> 24) & 255u, (h >> 16) & 255u, (h >> 8) & 255u) / 255.0f * 0.8f + 0.2f;
      }
    } else {
      shown = glm::vec3(v[0], v[1], v[2]);
    }
    for (int c = 0; c < 3; ++c) rgba[i * 4 + c] = LinearToSrgb8(shown[c]);
  }
  return rgba;
}

}  // namespace vkpt::internal

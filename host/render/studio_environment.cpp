#include "render/studio_environment.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "shared/sampling.h"

namespace vkpt::internal {
namespace {

// 1 inside the light's disc, 0 outside, with a smooth step over the outer third of its
// radius so the map's texels sample no hard edge.
float Disc(const StudioLight& light, glm::vec3 d) {
  const float cosAngle = std::clamp(glm::dot(glm::normalize(light.direction), d), -1.0f, 1.0f);
  const float angle = std::acos(cosAngle) * (180.0f / shader::kPi);
  const float t = std::clamp((light.radiusDegrees - angle) / (light.radiusDegrees / 3.0f), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

}  // namespace

float StudioRadiance(glm::vec3 d) {
  const float horizon = std::sin(2.0f * shader::kPi / 180.0f);
  const float t = std::clamp((d.y + horizon) / (2.0f * horizon), 0.0f, 1.0f);
  const float surround = kStudioFloor + (kStudioBackdrop - kStudioFloor) * t * t * (3.0f - 2.0f * t);
  return surround + kStudioKey.radiance * Disc(kStudioKey, d) + kStudioFill.radiance * Disc(kStudioFill, d);
}

EnvironmentMap StudioEnvironment(uint32_t width, uint32_t height) {
  std::vector<glm::vec3> radiance(size_t(width) * height);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      // The texel's centre as environment.h's EnvUvToDirection reads it, unrotated.
      const float phi = 2.0f * shader::kPi * ((x + 0.5f) / width - 0.5f);
      const float theta = shader::kPi * (y + 0.5f) / height;
      const glm::vec3 d(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
      radiance[size_t(y) * width + x] = glm::vec3(StudioRadiance(d));
    }
  return BuildEnvironmentMap(width, height, radiance, 1);
}

}  // namespace vkpt::internal

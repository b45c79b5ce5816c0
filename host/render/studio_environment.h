// The environment that lights a scene with no lights of its own: a neutral photo studio
// made up in code, so that a white model shows its form against a darker backdrop rather
// than vanishing into a uniform white world. A soft key light above and in front, a
// larger, dimmer fill low on the other side, a grey backdrop and a darker grey floor,
// all neutral in colour; importance-sampled like any environment map.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "render/environment_map.h"

namespace vkpt::internal {

// Its lights and backdrop, world space (+Y up, a default glTF camera looks along −Z).
struct StudioLight {
  glm::vec3 direction;  // unit, towards the light
  float radiusDegrees;  // angular radius, the edge softened over its outer third
  float radiance;
};
inline constexpr StudioLight kStudioKey{{0.40f, 0.80f, 0.45f}, 20.0f, 8.0f};
inline constexpr StudioLight kStudioFill{{-0.75f, 0.25f, 0.60f}, 30.0f, 0.8f};
inline constexpr float kStudioBackdrop = 0.20f;  // above the horizon
inline constexpr float kStudioFloor = 0.08f;     // below it, blended over ±2° at the horizon

// The studio's radiance from direction `d` (unit, world space).
float StudioRadiance(glm::vec3 d);

// The studio as a map of width × height texels (the texel centres' radiance), with its
// sampling distribution.
EnvironmentMap StudioEnvironment(uint32_t width = 256, uint32_t height = 128);

}  // namespace vkpt::internal

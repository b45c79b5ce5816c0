// The environment map as both renderers read it (shaders/shared/environment.h): radiance
// texels and the CDFs of its importance-sampling distribution.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "shared/layout.h"

namespace vkpt::internal {

struct EnvironmentMap {
  uint32_t width = 0, height = 0;  // 0 × 0: no map
  std::vector<glm::vec4> texels;   // (RGB radiance, 0), row-major, row 0 the top (v = 0)
  std::vector<float> cdf;          // conditional CDFs per row, then the marginal (layout.h)
  double buildMs = 0.0;            // time BuildEnvironmentMap took for the distribution
};

// Host memory per texel of an EnvironmentMap and of building it: texels, CDF and the
// weights, for the memory budget before BuildEnvironmentMap allocates them.
constexpr uint64_t kEnvironmentBytesPerTexel = sizeof(glm::vec4) + 2 * sizeof(float);

// The map of width × height linear RGB texels (row 0 on top; finite, non-negative) with
// its sampling distribution, built on `threads` threads (0: all cores).
EnvironmentMap BuildEnvironmentMap(uint32_t width, uint32_t height, std::span<const glm::vec3> radiance,
                                   unsigned threads = 0);

// Sets the frame's map fields: its size, the radiance scale and the rotation about +Y
// (degrees, counter-clockwise seen from above; see shared/environment.h).
void SetEnvironmentParams(shader::FrameParams& params, const EnvironmentMap& env, float rotationDegrees,
                          float intensity);

}  // namespace vkpt::internal

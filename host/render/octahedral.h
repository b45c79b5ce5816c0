// The host half of the octahedral normal encoding that shaders/shared/shading_normal.h
// decodes (Cigolle et al. 2014): unit vectors → two snorm16 in one uint.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace vkpt::internal {

// The code of `unit` (length 1) whose decoding is nearest to it: of the four snorm16
// grid points around its projection, the one with the smallest angular error
// ("precise" encoding, Cigolle et al. 2014 §3). Axes and diagonals are exact.
uint32_t EncodeOctahedral(glm::vec3 unit);

}  // namespace vkpt::internal

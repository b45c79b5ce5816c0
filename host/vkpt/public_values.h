// The engine's values as the public records (vkpt/scene_info.h, vkpt/parameters.h) hold
// them: floats and bools as they are, glm vectors as arrays.
#pragma once

#include <array>

#include <glm/glm.hpp>

namespace vkpt::internal {

inline float Public(float v) { return v; }
inline bool Public(bool v) { return v; }
inline std::array<float, 3> Public(glm::vec3 v) { return {v.x, v.y, v.z}; }

}  // namespace vkpt::internal

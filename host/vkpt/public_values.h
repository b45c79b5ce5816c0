// The engine's values as the public records (vkpt/scene_info.h, vkpt/parameters.h) hold
// them: floats and bools as they are, glm vectors as arrays (of floats), a quaternion as
// glTF writes it (x, y, z, w).
#pragma once

#include <array>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace vkpt::internal {

inline float Public(float v) { return v; }
inline bool Public(bool v) { return v; }
inline std::array<float, 3> Public(glm::vec3 v) { return {v.x, v.y, v.z}; }
inline std::array<float, 3> Public(glm::dvec3 v) { return Public(glm::vec3(v)); }
inline std::array<float, 4> Public(glm::dquat q) {
  return {float(q.x), float(q.y), float(q.z), float(q.w)};
}  // x, y, z, w

}  // namespace vkpt::internal

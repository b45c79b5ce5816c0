#include <algorithm>
#include <cmath>

#include "scene/scene.h"

namespace vkpt {

Camera DefaultCamera(const Bounds3f& bounds) {
  Camera cam;
  cam.name = "(default: framing the scene)";
  cam.yfov = 0.8f;  // ~46°, a normal lens
  glm::vec3 center = bounds.Center();
  float radius = std::max(0.5f * glm::length(bounds.Diagonal()), 1e-6f);
  // Far enough that the bounding sphere fits inside the vertical field of view.
  float distance = radius / std::sin(0.5f * cam.yfov) * 1.05f;
  cam.position = center + glm::vec3(0.0f, 0.0f, distance);
  return cam;  // forward −Z, up +Y, right +X: the glTF default orientation
}

}  // namespace vkpt

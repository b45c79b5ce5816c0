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
  // From the front (+Z), a little above and to the right: an oblique view, so that a
  // model made of axis-aligned planes is never seen exactly edge-on.
  glm::vec3 back = glm::normalize(glm::vec3(0.4f, 0.35f, 1.0f));
  cam.position = center + back * distance;
  cam.forward = -back;
  cam.right = glm::normalize(glm::cross(cam.forward, glm::vec3(0.0f, 1.0f, 0.0f)));
  cam.up = glm::cross(cam.right, cam.forward);
  return cam;
}

}  // namespace vkpt

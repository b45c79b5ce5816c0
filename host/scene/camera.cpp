#include <algorithm>
#include <cmath>

#include "scene/scene.h"
#include "util/error.h"

namespace vkpt::internal {

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

namespace {

// `cam` at `from` looking along the unit `forward`, with `up` (not along it) up.
Camera Aimed(Camera cam, glm::vec3 from, glm::vec3 forward, glm::vec3 up) {
  cam.position = from;
  cam.forward = forward;
  cam.right = glm::normalize(glm::cross(forward, up));
  cam.up = glm::cross(cam.right, cam.forward);
  return cam;
}

}  // namespace

Camera LookAt(Camera cam, glm::vec3 from, glm::vec3 at, glm::vec3 up) {
  const glm::vec3 view = at - from;
  if (!(glm::length(view) > 0.0f)) throw Error("the camera's look-at point is where it stands");
  const glm::vec3 forward = glm::normalize(view);
  // sin of the angle between the view and `up`: below 1e-4 the image's roll is undefined.
  if (!(glm::length(glm::cross(forward, up)) > 1e-4f * glm::length(up)))
    throw Error("the camera's up direction lies along its view");
  return Aimed(cam, from, forward, up);
}

Camera PlacedByMatrix(Camera cam, const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) throw Error("the camera matrix has a value that is not finite");
  if (m[0][3] != 0.0f || m[1][3] != 0.0f || m[2][3] != 0.0f || m[3][3] != 1.0f)
    throw Error("the camera matrix is not affine: its last row must be 0, 0, 0, 1");
  const glm::vec3 back(m[2]), up(m[1]), from(m[3]);
  if (!(glm::length(glm::cross(back, up)) > 1e-6f * glm::length(back) * glm::length(up)))
    throw Error("the camera matrix is singular: its −Z and +Y axes must be independent");
  return Aimed(cam, from, -glm::normalize(back), up);
}

Camera Orbit(Camera cam, glm::vec3 pivot, glm::vec3 up, float degrees) {
  // Rodrigues' rotation about the unit axis k: v cos θ + (k × v) sin θ + k (k·v)(1 − cos θ).
  const glm::vec3 k = glm::normalize(up);
  const float theta = glm::radians(degrees), c = std::cos(theta), s = std::sin(theta);
  auto turn = [&](glm::vec3 v) { return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1.0f - c); };
  cam.position = pivot + turn(cam.position - pivot);
  cam.forward = turn(cam.forward);
  cam.up = turn(cam.up);
  cam.right = turn(cam.right);
  return cam;
}

}  // namespace vkpt::internal

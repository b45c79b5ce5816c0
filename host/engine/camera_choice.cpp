#include "engine/camera_choice.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "util/error.h"

namespace vkpt::internal {
namespace {

Camera SceneCamera(const Scene& scene, const CameraSettings& c, const std::string& path) {
  const uint32_t index = c.index.value_or(0);
  if (scene.cameras.empty()) {
    if (c.index) throw Error(path + ": camera " + std::to_string(index) + " asked for, but the scene has no cameras");
    return DefaultCamera(scene.bounds);
  }
  if (index >= scene.cameras.size())
    throw Error(path + ": camera " + std::to_string(index) + " is out of range; the scene has " +
                std::to_string(scene.cameras.size()) + " camera(s)");
  return scene.cameras[index];
}

}  // namespace

Camera ChooseCamera(const Scene& scene, const CameraSettings& c, const std::string& path) {
  Camera cam = SceneCamera(scene, c, path);
  if (c.matrix) {
    try {
      cam = PlacedByMatrix(cam, *c.matrix);
    } catch (const Error& e) {
      throw Error(path + ": " + e.what());
    }
    cam.name += " placed by a matrix";
  }
  const glm::vec3 up = c.up.value_or(glm::vec3(0.0f, 1.0f, 0.0f));
  const glm::vec3 pivot = c.lookAt.value_or(scene.bounds.Center());
  try {
    if (c.lookFrom || c.lookAt || c.up) {
      const glm::vec3 from = c.lookFrom.value_or(cam.position);
      const glm::vec3 at = c.lookAt ? pivot : c.lookFrom ? scene.bounds.Center() : cam.position + cam.forward;
      cam = LookAt(cam, from, at, up);
      cam.name += " moved by --look-from/--look-at/--up";
    }
    if (c.orbit) {
      cam = Orbit(cam, pivot, up, float(*c.orbit));
      cam.name += ", turned by --orbit";
    }
  } catch (const Error& e) {
    throw Error(path + ": " + e.what());
  }
  if (c.fov) {
    if (cam.orthographic)
      throw Error(path + ": a field of view is for perspective cameras, and camera " +
                  std::to_string(c.index.value_or(0)) + " is orthographic");
    cam.yfov = float(*c.fov * 3.14159265358979323846 / 180.0);
  }
  return cam;
}

glm::uvec2 ImageSize(const Camera& cam, const PictureSettings& p, const std::string& path) {
  // In double: the side that follows a ratio far from 1 may be beyond any integer's reach.
  const double aspect = cam.aspectRatio > 0.0f ? double(cam.aspectRatio) : 1.0;
  const double width = p.width ? double(*p.width) : p.height ? std::round(*p.height * aspect) : 512.0;
  const double height = p.height ? double(*p.height) : std::round(width / aspect);
  if (!(width <= kMaxImageSide && height <= kMaxImageSide)) {
    char what[160];
    std::snprintf(what, sizeof what,
                  "the camera's aspectRatio %g asks for a %.0f × %.0f image, beyond %u pixels a side", aspect, width,
                  height, kMaxImageSide);
    throw Error(path + ": " + what + "; give --width and --height");
  }
  return {uint32_t(std::max(width, 1.0)), uint32_t(std::max(height, 1.0))};
}

}  // namespace vkpt::internal

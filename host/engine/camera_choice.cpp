#include "engine/camera_choice.h"

#include <algorithm>
#include <cmath>

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

glm::uvec2 ImageSize(const Camera& cam, const PictureSettings& p) {
  const float aspect = cam.aspectRatio > 0.0f ? cam.aspectRatio : 1.0f;
  const uint32_t width = p.width.value_or(p.height ? uint32_t(std::lround(*p.height * aspect)) : 512u);
  const uint32_t height = p.height.value_or(uint32_t(std::lround(width / aspect)));
  return {std::max(1u, std::min(width, 16384u)), std::max(1u, std::min(height, 16384u))};
}

}  // namespace vkpt::internal

#include "viewer/view_camera.h"

#include <algorithm>
#include <cmath>

namespace vkpt::internal {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr glm::dvec3 kWorldUp{0.0, 1.0, 0.0};
// A distance kept within what a double's scene can mean, whatever the wheel says.
constexpr double kNearest = 1e-9, kFarthest = 1e15;

bool Finite(glm::dvec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }
bool Finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The height of the view's plane through the target that the window's height shows.
double ViewHeightAtTarget(const ViewCamera& view) {
  return 2.0 * view.distance * std::tan(0.5 * view.fovDegrees * kPi / 180.0);
}

}  // namespace

glm::dvec3 ViewCamera::Forward() const {
  return {-std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

glm::dvec3 ViewCamera::Right() const { return {std::cos(yaw), 0.0, -std::sin(yaw)}; }

glm::dvec3 ViewCamera::Up() const { return glm::cross(Right(), Forward()); }

glm::dvec3 ViewCamera::Eye() const { return target - Forward() * distance; }

vkpt::Camera ViewCamera::ForRender() const {
  const glm::dvec3 eye = Eye();
  vkpt::Camera c;
  c.lookFrom = std::array<float, 3>{float(eye.x), float(eye.y), float(eye.z)};
  c.lookAt = std::array<float, 3>{float(target.x), float(target.y), float(target.z)};
  c.up = std::array<float, 3>{0.0f, 1.0f, 0.0f};
  c.fovDegrees = fovDegrees;
  return c;
}

ViewCamera FromCamera(const vkpt::CameraInfo& info, const SceneBox& box) {
  const glm::dvec3 eye(info.position[0], info.position[1], info.position[2]);
  const glm::dvec3 forward = glm::normalize(glm::dvec3(info.forward[0], info.forward[1], info.forward[2]));
  ViewCamera view;
  view.pitch = std::clamp(std::asin(std::clamp(forward.y, -1.0, 1.0)), -kMaxPitch, kMaxPitch);
  view.yaw = std::atan2(-forward.x, -forward.z);
  view.distance = std::max(glm::dot(box.Center() - eye, forward), std::max(0.1 * box.Radius(), kNearest));
  view.target = eye + view.Forward() * view.distance;
  view.fovDegrees =
      info.orthographic || !(info.yfovDegrees > 0.0 && info.yfovDegrees < 180.0) ? 45.0 : info.yfovDegrees;
  return view;
}

ViewCamera FrameAll(const ViewCamera& view, const SceneBox& box, double aspect) {
  if (!(aspect > 0.0) || !std::isfinite(aspect)) aspect = 1.0;
  const double halfY = 0.5 * view.fovDegrees * kPi / 180.0;
  const double halfX = std::atan(std::tan(halfY) * aspect);
  ViewCamera framed = view;
  framed.target = box.Center();
  framed.distance =
      std::clamp(std::max(box.Radius(), 1e-6) / std::sin(std::min(halfX, halfY)) * 1.05, kNearest, kFarthest);
  return framed;
}

ViewCamera Orbit(const ViewCamera& view, glm::dvec2 pixels, double height) {
  if (!Finite(pixels) || !(height > 0.0)) return view;
  ViewCamera turned = view;
  turned.yaw = std::remainder(view.yaw - 2.0 * kPi * pixels.x / height, 2.0 * kPi);
  turned.pitch = std::clamp(view.pitch - 2.0 * kPi * pixels.y / height, -kMaxPitch, kMaxPitch);
  return turned;
}

ViewCamera Pan(const ViewCamera& view, glm::dvec2 pixels, double height) {
  if (!Finite(pixels) || !(height > 0.0)) return view;
  const double unitsPerPixel = ViewHeightAtTarget(view) / height;
  ViewCamera moved = view;
  moved.target += (-pixels.x * view.Right() + pixels.y * view.Up()) * unitsPerPixel;
  return Finite(moved.target) ? moved : view;
}

ViewCamera Dolly(const ViewCamera& view, double clicks) {
  if (!std::isfinite(clicks)) return view;
  ViewCamera moved = view;
  moved.distance = std::clamp(view.distance * std::pow(0.9, std::clamp(clicks, -1000.0, 1000.0)), kNearest, kFarthest);
  return moved;
}

ViewCamera Fly(const ViewCamera& view, glm::dvec3 step) {
  if (!Finite(step)) return view;
  ViewCamera moved = view;
  moved.target += step.x * view.Right() + step.y * kWorldUp + step.z * view.Forward();
  return Finite(moved.target) ? moved : view;
}

}  // namespace vkpt::internal

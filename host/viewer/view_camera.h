// An interactive viewer's camera as a user moves it: an eye turning about a
// target at some distance, by a yaw about glTF's up (+Y) and a pitch above the horizon,
// with a vertical field of view and no roll. Every control is a pure function from one
// ViewCamera to the next, so the mathematics is tested without a window
// (tests/test_view_camera.cpp), for a window to map mouse and keys onto. The drag
// conventions are three.js OrbitControls' (three-gpu-pathtracer's viewer): a drag across
// the window's height turns the eye once around; the point under the cursor follows a pan.
#pragma once

#include <glm/glm.hpp>

#include "vkpt/vkpt.h"

namespace vkpt::internal {

struct ViewCamera {
  glm::dvec3 target{0.0};
  double distance = 1.0;     // from the eye to the target, > 0
  double yaw = 0.0;          // radians about +Y; 0 looks along −Z
  double pitch = 0.0;        // radians above the horizon, within ±kMaxPitch
  double fovDegrees = 45.0;  // vertical, in (0, 180)

  glm::dvec3 Forward() const;  // unit, from the eye towards the target
  glm::dvec3 Right() const;    // unit and horizontal
  glm::dvec3 Up() const;       // unit, completing the frame
  glm::dvec3 Eye() const;
  // As the library takes it (lookFrom, lookAt, +Y up, fovDegrees): the command line's
  // --look-from, --look-at and --fov.
  vkpt::Camera ForRender() const;
};

// The pitch stays a degree short of straight up or down, where yaw loses its meaning.
inline constexpr double kMaxPitch = 89.0 * 3.14159265358979323846 / 180.0;

// The scene's axis-aligned bounds, as Scene::Stats() gives them.
struct SceneBox {
  glm::dvec3 lo{0.0}, hi{0.0};
  glm::dvec3 Center() const { return 0.5 * (lo + hi); }
  double Radius() const { return 0.5 * glm::length(hi - lo); }
};

// The file's camera `info` as a ViewCamera: its eye and line of sight (its roll dropped),
// the target where that line passes the scene's centre, but at least a tenth of the
// scene's radius ahead. An orthographic camera keeps a 45° field of view.
ViewCamera FromCamera(const vkpt::CameraInfo& info, const SceneBox& box);

// Looking along the view's direction at the centre of `box`, from the distance at which
// its bounding sphere fills the vertical and the horizontal field of view (`aspect`:
// width / height), whichever is narrower, with 5 % to spare.
ViewCamera FrameAll(const ViewCamera& view, const SceneBox& box, double aspect);

// A drag of `pixels` (x right, y down) with the left button, in a window `height` pixels
// high: the eye turns about the target, right drags turning it left (the scene follows
// the cursor), down drags raising it.
ViewCamera Orbit(const ViewCamera& view, glm::dvec2 pixels, double height);

// A drag with the right or middle button: eye and target move in the view's plane so that
// a point at the target's depth stays under the cursor.
ViewCamera Pan(const ViewCamera& view, glm::dvec2 pixels, double height);

// Wheel clicks (positive: towards the target): each brings the eye 10 % nearer.
ViewCamera Dolly(const ViewCamera& view, double clicks);

// Flying (W/A/S/D/Q/E): eye and target move together by `step` scene units along the
// view's right (x) and forward (z) directions and the world's up (y).
ViewCamera Fly(const ViewCamera& view, glm::dvec3 step);

}  // namespace vkpt::internal

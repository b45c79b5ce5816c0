// The viewer's camera controls (viewer/view_camera.h) without a window: each keeps what it
// should (the target, the distance, a point under the cursor), moves what it should by the
// amount it says, frames the whole scene, and ignores input that is not a number.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "viewer/view_camera.h"

namespace vkpt::internal {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTight = 1e-9;

void ExpectNear(glm::dvec3 a, glm::dvec3 b, double tolerance = kTight) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

// Where `point` appears in a window `size` pixels large (x right, y down), as a pinhole
// camera with the view's frame and vertical field of view projects it.
glm::dvec2 Project(const ViewCamera& view, glm::dvec3 point, glm::dvec2 size) {
  const glm::dvec3 d = point - view.Eye();
  const double z = glm::dot(d, view.Forward());
  const double scale = 0.5 * size.y / std::tan(0.5 * view.fovDegrees * kPi / 180.0) / z;
  return {0.5 * size.x + glm::dot(d, view.Right()) * scale, 0.5 * size.y - glm::dot(d, view.Up()) * scale};
}

ViewCamera Some() {
  ViewCamera v;
  v.target = {1.0, 2.0, -3.0};
  v.distance = 7.0;
  v.yaw = 0.7;
  v.pitch = -0.3;
  v.fovDegrees = 50.0;
  return v;
}

TEST(ViewCamera, FrameIsOrthonormalAndLooksAtTheTarget) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> yaw(-kPi, kPi), pitch(-kMaxPitch, kMaxPitch);
  for (int i = 0; i < 100; ++i) {
    ViewCamera v = Some();
    v.yaw = yaw(rng);
    v.pitch = pitch(rng);
    EXPECT_NEAR(glm::length(v.Forward()), 1.0, kTight);
    EXPECT_NEAR(glm::length(v.Right()), 1.0, kTight);
    EXPECT_NEAR(glm::length(v.Up()), 1.0, kTight);
    EXPECT_NEAR(glm::dot(v.Forward(), v.Right()), 0.0, kTight);
    EXPECT_NEAR(v.Right().y, 0.0, kTight);  // no roll
    EXPECT_GT(v.Up().y, 0.0);
    EXPECT_NEAR(glm::length(v.target - v.Eye()), v.distance, kTight);
  }
  ViewCamera front;
  ExpectNear(front.Forward(), {0, 0, -1});
  ExpectNear(front.Right(), {1, 0, 0});
  ExpectNear(front.Up(), {0, 1, 0});
}

TEST(ViewCamera, ForRenderIsTheLookAtOfTheCommandLine) {
  const ViewCamera v = Some();
  const vkpt::Camera c = v.ForRender();
  ASSERT_TRUE(c.lookFrom && c.lookAt && c.up && c.fovDegrees);
  ExpectNear({(*c.lookFrom)[0], (*c.lookFrom)[1], (*c.lookFrom)[2]}, v.Eye(), 1e-5);
  ExpectNear({(*c.lookAt)[0], (*c.lookAt)[1], (*c.lookAt)[2]}, v.target, 1e-6);
  ExpectNear({(*c.up)[0], (*c.up)[1], (*c.up)[2]}, {0, 1, 0});
  EXPECT_EQ(*c.fovDegrees, 50.0);
  EXPECT_FALSE(c.index || c.matrix);
}

TEST(ViewCamera, OrbitTurnsTheEyeAboutTheTarget) {
  const ViewCamera v = Some();
  const glm::dvec2 window(640, 480);
  for (glm::dvec2 drag : {glm::dvec2(35, 0), glm::dvec2(-120, 40), glm::dvec2(3, -77)}) {
    const ViewCamera t = Orbit(v, drag, window.y);
    ExpectNear(t.target, v.target);
    EXPECT_EQ(t.distance, v.distance);
    const glm::dvec2 centre = Project(t, t.target, window);
    EXPECT_NEAR(centre.x, 320, 1e-9);
    EXPECT_NEAR(centre.y, 240, 1e-9);
  }
  // A drag across the window's height turns once around; a quarter of it a quarter turn,
  // a right drag carrying the eye to the left of where it was.
  ExpectNear(Orbit(v, {480, 0}, 480).Eye(), v.Eye());
  ViewCamera front;
  front.distance = 2.0;
  ExpectNear(Orbit(front, {120, 0}, 480).Eye(), {-2, 0, 0});
  // A down drag raises the eye; the pitch stops short of the pole.
  EXPECT_GT(Orbit(front, {0, 10}, 480).Eye().y, 0.0);
  EXPECT_EQ(Orbit(front, {0, 1e6}, 480).pitch, -kMaxPitch);
  EXPECT_EQ(Orbit(front, {0, -1e6}, 480).pitch, kMaxPitch);
}

TEST(ViewCamera, PanKeepsThePointUnderTheCursor) {
  const glm::dvec2 window(800, 600);
  for (double fov : {20.0, 50.0, 100.0}) {
    ViewCamera v = Some();
    v.fovDegrees = fov;
    // A point at the target's depth, off the centre.
    const glm::dvec3 point = v.target + 0.8 * v.Right() - 0.5 * v.Up();
    const glm::dvec2 before = Project(v, point, window);
    for (glm::dvec2 drag : {glm::dvec2(50, 0), glm::dvec2(-13, 91), glm::dvec2(0, -300)}) {
      const ViewCamera p = Pan(v, drag, window.y);
      EXPECT_EQ(p.distance, v.distance);
      EXPECT_EQ(p.yaw, v.yaw);
      ExpectNear(p.Eye() - v.Eye(), p.target - v.target);
      const glm::dvec2 after = Project(p, point, window);
      EXPECT_NEAR(after.x, before.x + drag.x, 1e-6) << fov;
      EXPECT_NEAR(after.y, before.y + drag.y, 1e-6) << fov;
    }
  }
}

TEST(ViewCamera, DollyBringsTheEyeNearerByATenthAClick) {
  const ViewCamera v = Some();
  EXPECT_NEAR(Dolly(v, 1).distance, 0.9 * v.distance, kTight);
  EXPECT_NEAR(Dolly(v, -3).distance, v.distance / (0.9 * 0.9 * 0.9), kTight);
  EXPECT_NEAR(Dolly(Dolly(v, 5), -5).distance, v.distance, kTight);
  ExpectNear(Dolly(v, 4).target, v.target);
  // However far the wheel turns, the eye stays in front of the target and finite.
  for (double clicks : {1e6, -1e6, 1e308, -1e308}) {
    const double d = Dolly(v, clicks).distance;
    EXPECT_TRUE(d > 0.0 && std::isfinite(d)) << clicks;
  }
}

TEST(ViewCamera, FlyMovesEyeAndTargetTogether) {
  const ViewCamera v = Some();
  const ViewCamera forward = Fly(v, {0, 0, 2});
  ExpectNear(forward.Eye(), v.Eye() + 2.0 * v.Forward());
  ExpectNear(Fly(v, {-1, 0, 0}).Eye(), v.Eye() - v.Right());
  ExpectNear(Fly(v, {0, 3, 0}).target, v.target + glm::dvec3(0, 3, 0));  // Q/E: the world's up
  EXPECT_EQ(forward.yaw, v.yaw);
  EXPECT_EQ(forward.distance, v.distance);
}

TEST(ViewCamera, FrameAllFitsEveryCornerInTheWindow) {
  const SceneBox box{{-1, 0, -2}, {3, 5, 1}};
  for (double aspect : {0.5, 1.0, 2.0})
    for (double fov : {20.0, 45.0, 90.0}) {
      ViewCamera v = Some();
      v.fovDegrees = fov;
      const ViewCamera f = FrameAll(v, box, aspect);
      ExpectNear(f.target, box.Center());
      EXPECT_EQ(f.yaw, v.yaw);
      const glm::dvec2 window(480 * aspect, 480);
      double widest = 0.0;  // how far out the furthest corner lies, as a share of the half window
      for (int c = 0; c < 8; ++c) {
        const glm::dvec3 corner(c & 1 ? box.hi.x : box.lo.x, c & 2 ? box.hi.y : box.lo.y, c & 4 ? box.hi.z : box.lo.z);
        const glm::dvec2 s = Project(f, corner, window);
        widest = std::max({widest, std::abs(s.x / window.x - 0.5) * 2, std::abs(s.y / window.y - 0.5) * 2});
      }
      EXPECT_LT(widest, 1.0) << aspect << " " << fov;
      EXPECT_GT(widest, 0.5) << aspect << " " << fov;  // framed, not lost in the distance
    }
}

TEST(ViewCamera, FromCameraKeepsTheFilesEyeAndLineOfSight) {
  const SceneBox box{{-1, -1, -1}, {1, 1, 1}};
  vkpt::CameraInfo info;
  info.position = {0.5f, 2.0f, 6.0f};
  const glm::dvec3 forward = glm::normalize(glm::dvec3(-0.1, -0.3, -1.0));
  info.forward = {float(forward.x), float(forward.y), float(forward.z)};
  info.yfovDegrees = 39.6;
  const ViewCamera v = FromCamera(info, box);
  ExpectNear(v.Eye(), {0.5, 2.0, 6.0}, 1e-6);
  ExpectNear(v.Forward(), forward, 1e-6);
  EXPECT_NEAR(v.fovDegrees, 39.6, 1e-6);
  EXPECT_NEAR(v.distance, glm::dot(box.Center() - v.Eye(), forward), 1e-6);
  // Looking away from the scene, the target stays ahead; orthographic: a 45° lens.
  info.forward = {0.0f, 0.0f, 1.0f};
  info.orthographic = true;
  const ViewCamera away = FromCamera(info, box);
  EXPECT_NEAR(away.distance, 0.1 * box.Radius(), 1e-9);
  EXPECT_EQ(away.fovDegrees, 45.0);
}

TEST(ViewCamera, InputThatIsNotANumberChangesNothing) {
  const ViewCamera v = Some();
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const ViewCamera& same : {Orbit(v, {nan, 0}, 480), Orbit(v, {1, 1}, 0), Pan(v, {0, inf}, 480),
                                 Pan(v, {1e308, 0}, 1e-308), Dolly(v, nan), Fly(v, {0, nan, 0})}) {
    ExpectNear(same.target, v.target);
    EXPECT_EQ(same.distance, v.distance);
    EXPECT_EQ(same.yaw, v.yaw);
    EXPECT_EQ(same.pitch, v.pitch);
  }
  const ViewCamera framed = FrameAll(v, {{0, 0, 0}, {1, 1, 1}}, nan);
  EXPECT_TRUE(std::isfinite(framed.distance));
}

}  // namespace
}  // namespace vkpt::internal

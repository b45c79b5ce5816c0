// Cameras placed by a camera-to-world matrix (scene/scene.h PlacedByMatrix): the matrix's
// translation and axes become the camera's, whatever its scale; matrices that place no
// camera are refused with the reason.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

TEST(Camera, MatrixPlacesTheCameraAlongItsMinusZ) {
  Camera lens;
  lens.yfov = 0.7f;
  const glm::vec3 at(1.0f, -2.0f, 3.0f);
  glm::mat4 m = glm::translate(glm::mat4(1.0f), at);
  m = glm::rotate(m, 0.6f, glm::normalize(glm::vec3(1.0f, 2.0f, -0.5f)));
  for (float scale : {1.0f, 3.0f, 0.01f}) {
    const Camera cam = PlacedByMatrix(lens, glm::scale(m, glm::vec3(scale)));
    EXPECT_LT(glm::length(cam.position - at), 1e-6f) << scale;
    EXPECT_LT(glm::length(cam.forward + glm::normalize(glm::vec3(m[2]))), 1e-6f) << scale;
    EXPECT_LT(glm::length(cam.up - glm::normalize(glm::vec3(m[1]))), 1e-6f) << scale;
    EXPECT_LT(glm::length(cam.right - glm::normalize(glm::vec3(m[0]))), 1e-6f) << scale;
    EXPECT_EQ(cam.yfov, 0.7f);
  }
}

TEST(Camera, MatricesThatPlaceNoCameraAreRefused) {
  auto refusal = [](const glm::mat4& m) -> std::string {
    try {
      PlacedByMatrix(Camera{}, m);
    } catch (const Error& e) {
      return e.what();
    }
    return "(accepted)";
  };
  glm::mat4 nan(1.0f);
  nan[3][1] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(refusal(nan), "the camera matrix has a value that is not finite");
  glm::mat4 projective(1.0f);
  projective[2][3] = -1.0f;
  EXPECT_EQ(refusal(projective), "the camera matrix is not affine: its last row must be 0, 0, 0, 1");
  glm::mat4 flat(1.0f);
  flat[2] = glm::vec4(0.0f);
  EXPECT_EQ(refusal(flat), "the camera matrix is singular: its −Z and +Y axes must be independent");
  glm::mat4 parallel(1.0f);
  parallel[2] = glm::vec4(0.0f, 2.0f, 0.0f, 0.0f);
  EXPECT_EQ(refusal(parallel), "the camera matrix is singular: its −Z and +Y axes must be independent");
  EXPECT_EQ(refusal(glm::mat4(1.0f)), "(accepted)");
}

}  // namespace
}  // namespace vkpt::internal

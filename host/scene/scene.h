// The flat scene every renderer consumes: world-space triangles, materials and cameras.
// host/scene/gltf_loader.cpp fills it from a glTF file; nothing downstream knows glTF.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "shared/layout.h"
#include "util/bounds.h"

namespace vkpt {

using shader::Material;

// World-space triangle; (v1 - v0) × (v2 - v0) is the front-face normal (counter-clockwise
// winding, already corrected for mirroring transforms).
struct SceneTriangle {
  glm::vec3 v0, v1, v2;
  uint32_t material;
};

struct Camera {
  std::string name;
  glm::vec3 position{0.0f};
  glm::vec3 forward{0.0f, 0.0f, -1.0f};  // unit; the camera looks along its local −Z
  glm::vec3 up{0.0f, 1.0f, 0.0f};        // unit, orthogonal to forward
  glm::vec3 right{1.0f, 0.0f, 0.0f};     // unit, forward × up
  bool orthographic = false;
  float yfov = 0.0f;         // perspective: vertical field of view, radians
  float aspectRatio = 0.0f;  // width / height from the file; 0 when absent
  float ymag = 0.0f;         // orthographic: half the view height
  float xmag = 0.0f;         // orthographic: half the view width
};

struct Scene {
  std::string path;
  std::vector<SceneTriangle> triangles;
  std::vector<Material> materials;
  std::vector<std::string> materialNames;
  std::vector<Camera> cameras;  // in scene-graph order; --camera N picks one
  Bounds3f bounds;

  // What a user should know about what was (not) loaded; printed by -v.
  std::vector<std::string> warnings;
  std::vector<std::string> ignoredFeatures;
  // The loader's memory budget (--max-memory) and what it counted for this scene.
  uint64_t memoryLimit = 0, memoryCounted = 0;
};

// A camera framing the whole scene, for files that define none: looks along −Z at the
// centre of the bounds from far enough that the bounding sphere fits the view.
Camera DefaultCamera(const Bounds3f& bounds);

}  // namespace vkpt

// The flat scene every renderer consumes: world-space triangles with their vertex
// normals and colours, materials, cameras and punctual lights.
// host/gltf/gltf_loader.cpp fills it from a glTF file; nothing downstream knows glTF.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/material.h"
#include "util/bounds.h"

namespace vkpt::internal {

// World-space triangle; (v1 - v0) × (v2 - v0) is the front-face normal (counter-clockwise
// winding, already corrected for mirroring transforms).
struct SceneTriangle {
  glm::vec3 v0, v1, v2;
  uint32_t material;
};

// World-space unit vertex normals of one triangle (glTF NORMAL), in the order of its
// vertices, for smooth shading; all zero when the triangle has none and is shaded flat.
struct VertexNormals {
  glm::vec3 n0{0.0f}, n1{0.0f}, n2{0.0f};
  bool Present() const { return n0 != glm::vec3(0.0f); }
};

// COLOR_0 of one triangle's vertices (glTF §3.7.2.1), linear RGBA in [0, 1], in the order
// of its vertices; white for a triangle without them in a scene where others have them.
struct VertexColors {
  glm::vec4 c0{1.0f}, c1{1.0f}, c2{1.0f};
};

// TEXCOORD_0 (set0) and TEXCOORD_1 (set1) of one triangle's vertices, in the order of
// its vertices; 0 where the primitive lacks the set.
struct VertexUVs {
  glm::vec2 set0[3]{}, set1[3]{};
};

// TANGENT of one triangle's vertices in world space (xyz unit; w = ±1, the bitangent
// sign), or MikkTSpace tangents the loader generated; zero where none could be had.
struct VertexTangents {
  glm::vec4 t[3]{};
};

// A decoded image (glTF images[i]): RGBA8, row-major from the top row.
struct TextureImage {
  std::string name;  // for messages: images[i] "name"
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> rgba;
};

// A glTF sampler (§3.8.3): wrap modes and filters. The defaults are what glTF leaves to
// the renderer when a texture has no sampler, or a sampler no filter: repeat, trilinear.
struct TextureSampler {
  enum class Wrap { kRepeat, kClampToEdge, kMirroredRepeat };
  // minFilter's choice between mip levels: none (level 0 only), the nearest, or a blend of two.
  enum class Mip { kNone, kNearest, kLinear };
  Wrap wrapS = Wrap::kRepeat, wrapT = Wrap::kRepeat;
  bool magLinear = true;  // magFilter LINEAR; false: NEAREST
  bool minLinear = true;  // minFilter within a level LINEAR; false: NEAREST
  Mip mip = Mip::kLinear;
};

// A glTF texture as the materials use it: its image, its sampler and whether its RGB is
// sRGB-encoded colour. A glTF texture used both as colour and as data becomes two.
struct SceneTexture {
  uint32_t image = 0;  // into Scene::images
  TextureSampler sampler;
  bool srgb = false;
  uint32_t fileIndex = 0;  // the file's texture it was made from (glTF textures[i])
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

// A KHR_lights_punctual light placed by its node: infinitely small (point, spot) or
// infinitely far (directional). Not scaled by its node, as the extension demands.
struct PunctualLight {
  enum class Type { kPoint, kSpot, kDirectional } type = Type::kPoint;
  glm::vec3 position{0.0f};                // world space; unused for directional lights
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // unit, the way light travels: the node's world −Z
  glm::vec3 intensity{1.0f};               // color × intensity: candela for point/spot, lux for directional
  // As the file gives them: KHR_lights_punctual lights[light], its color and intensity.
  uint32_t light = 0;
  glm::vec3 color{1.0f};
  float lightIntensity = 1.0f;
  float range = 0.0f;                      // distance beyond which the light has no effect; 0 = infinite
  float cosInner = 0.0f, cosOuter = 0.0f;  // spot: full intensity within the inner cone, none outside the outer
  std::string name;
};

// One placement of a glTF node's mesh: the node's own, or one per EXT_mesh_gpu_instancing
// instance (`placement`, 0 without). Its index in Scene::meshInstances is its instance id.
struct MeshInstance {
  uint32_t node = 0, mesh = 0, placement = 0;
};

// Scene triangles [firstTriangle, the next run's firstTriangle) belong to mesh instance
// `instance`.
struct TriangleRun {
  uint32_t firstTriangle = 0, instance = 0;
};

// A glTF animation: its name ("" when it has none) and its length in seconds.
struct AnimationSummary {
  std::string name;
  double duration = 0.0;
};

// The animations' names, in the file's order.
inline std::vector<std::string> Names(const std::vector<AnimationSummary>& animations) {
  std::vector<std::string> names;
  for (const AnimationSummary& a : animations) names.push_back(a.name);
  return names;
}

struct Scene {
  std::string path;
  std::vector<SceneTriangle> triangles;
  // Parallel to `triangles`, or empty when no triangle has normals: a file without any
  // costs no memory for them (36 bytes a triangle at 10 M triangles is 360 MB).
  std::vector<VertexNormals> normals;
  // Parallel to `triangles`, or empty when no triangle has COLOR_0.
  std::vector<VertexColors> colors;
  // Parallel to `triangles`, or empty when no material has a texture.
  std::vector<VertexUVs> uvs;
  // Parallel to `triangles`, or empty when no material has a normal texture.
  std::vector<VertexTangents> tangents;
  std::vector<Material> materials;
  std::vector<SceneTexture> textures;  // what MaterialTexture::texture indexes
  std::vector<TextureImage> images;
  std::vector<std::string> materialNames;
  std::vector<Camera> cameras;  // in scene-graph order; --camera N picks one
  // KHR_materials_variants: the file's variant names, and the one rendered (−1: none, the
  // primitives' own materials).
  std::vector<std::string> materialVariants;
  int variant = -1;
  // The file's animations, the one posing the scene (−1: none, the nodes' own transforms)
  // and the time it is read at, in seconds.
  std::vector<AnimationSummary> animations;
  int animation = -1;
  double animationTime = 0.0;
  std::vector<PunctualLight> lights;  // in scene-graph order, one per light node
  Bounds3f bounds;
  // Where the triangles came from (the id AOVs, scene/scene_ids.h): the mesh instances in
  // scene-graph order, the runs of triangles each placed, in triangle order, and the file's
  // node and mesh names ("nodes[i]", "meshes[i]" where it has none). Empty for a scene made
  // in code.
  std::vector<MeshInstance> meshInstances;
  std::vector<TriangleRun> triangleRuns;
  std::vector<std::string> nodeNames, meshNames;

  // What a user should know about what was (not) loaded; printed by -v.
  uint32_t generatedTangentPrimitives = 0;  // normal-mapped primitives given MikkTSpace tangents
  std::vector<std::string> warnings;
  std::vector<std::string> ignoredFeatures;
  // ContentHash of the glTF file and every buffer it loaded (for reports: --stats).
  uint64_t contentHash = 0;
  // The loader's memory budget (--max-memory) and what it counted for this scene.
  uint64_t memoryLimit = 0, memoryCounted = 0;
};

// Whether some material has a texture (and so every triangle has texture coordinates).
inline bool HasMaterialTextures(const Scene& scene) {
  for (const Material& m : scene.materials)
    if (m.Textured()) return true;
  return false;
}

// A camera framing the whole scene, for files that define none: looks along −Z at the
// centre of the bounds from far enough that the bounding sphere fits the view.
Camera DefaultCamera(const Bounds3f& bounds);
// `cam` moved to `from` and aimed at `at`, turned about its view so that `up` points up in
// the image; its lens (perspective or orthographic, field of view) unchanged. Throws
// Error when `from` and `at` coincide or `up` lies along the view.
Camera LookAt(Camera cam, glm::vec3 from, glm::vec3 at, glm::vec3 up);
// `cam` placed by a camera-to-world matrix (column-major, as glTF nodes hold them): at its
// translation, looking along its −Z with its +Y up; scale and shear do not distort the
// view. Throws Error for a matrix that is not finite and affine, or whose −Z and +Y are
// not independent.
Camera PlacedByMatrix(Camera cam, const glm::mat4& cameraToWorld);
// `cam` turned by `degrees` about the axis along `up` through `pivot`, counter-clockwise
// seen from above (from where `up` points): position, view and up turn together.
Camera Orbit(Camera cam, glm::vec3 pivot, glm::vec3 up, float degrees);

}  // namespace vkpt::internal

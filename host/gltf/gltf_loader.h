// glTF 2.0 (.gltf / .glb) → Scene.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scene/load_limits.h"
#include "scene/scene.h"

namespace vkpt::internal {

// What to render of a file beyond its default scene.
struct SceneChoice {
  std::string variant{};    // a KHR_materials_variants variant, by name or index; "": the primitives' own materials
  std::string animation{};  // an animation, by name or index; "": the nodes' own transforms
  double time = 0.0;        // seconds into the animation (LoadedScene: of its first pose)
};

// A node of the file (vkpt::Scene::Nodes): what it links to, and its local transform as
// the file places it — a matrix as its decomposition, which drops any shear.
struct NodeSummary {
  std::string name;
  int mesh = -1, camera = -1, light = -1;  // −1: none
  std::vector<uint32_t> children;
  glm::dvec3 translation{0.0};
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 scale{1.0};
  bool matrix = false;
};

// A mesh of the file: per triangle primitive, its material (in the chosen variant) and
// its triangle count.
struct MeshSummary {
  std::string name;
  std::vector<std::pair<uint32_t, uint64_t>> primitives;
};

// A KHR_lights_punctual light of the file: its colour and intensity.
struct LightSource {
  glm::dvec3 color{1.0};
  double intensity = 1.0;
};

// Changes to the file's nodes, lights and materials, by index, and to its choice of variant
// and animation (vkpt::Scene::Update).
struct NodeEdit {
  std::optional<glm::dvec3> translation, scale;
  std::optional<glm::dquat> rotation;
};
struct LightEdit {
  std::optional<glm::dvec3> color;
  std::optional<double> intensity;
};
struct AssetEdits {
  std::map<uint32_t, NodeEdit> nodes;
  std::map<uint32_t, LightEdit> lights;
  std::map<uint32_t, Material> materials;         // replaced whole
  std::optional<std::string> variant, animation;  // as SceneChoice spells them
  bool Empty() const { return nodes.empty() && lights.empty() && materials.empty() && !variant && !animation; }
};

// A glTF file read, checked and decoded once — materials, textures, meshes, skins and
// the chosen animation — and posed any number of times.
class GltfAsset {
 public:
  // Reads `path` as LoadGltf does, but poses nothing yet.
  GltfAsset(const std::string& path, const LoadLimits& limits = {}, const SceneChoice& choice = {});
  ~GltfAsset();
  GltfAsset(GltfAsset&&) = default;
  GltfAsset& operator=(GltfAsset&&) = default;

  // Poses the scene `time` seconds into the chosen animation (the nodes' own transforms
  // without one): its triangles, cameras, lights and bounds are replaced.
  void PoseAt(double time);
  // Frees the parsed file and its decoded meshes, keeping the posed scene: after the
  // last PoseAt (a single image), before the BVH is built. PoseAt may not follow.
  void ReleaseSource();
  const Scene& scene() const;
  Scene TakeScene();  // the asset is spent

  // The file's nodes, meshes and lights (gltf_edits.cpp); not after ReleaseSource.
  std::vector<NodeSummary> Nodes() const;
  std::vector<MeshSummary> Meshes() const;
  std::vector<LightSource> Lights() const;
  // Applies `edits` as a file so edited (or loaded with that choice) would load — a node
  // given a translation, rotation or scale loses its matrix, its other two taken from the
  // matrix's decomposition; the meshes whose decoding a new variant or material changes
  // are decoded again; the memory is counted again where the tangents or the animation
  // change — and poses the scene at `time` unless only materials changed and no mesh was
  // decoded again. Returns whether the scene's triangles may have changed (else only its
  // materials and lights did). Throws Error where the file so edited would be refused,
  // an unknown variant or animation, or memory beyond the limit; then the asset is as it
  // was. Not after ReleaseSource.
  bool Edit(const AssetEdits& edits, double time);

  struct Parts;  // the parsed file, its decoded meshes and rest pose (gltf_loader.cpp)

 private:
  void Kept(const char* what) const;  // throws std::logic_error naming `what` after ReleaseSource
  std::unique_ptr<Parts> parts_;
};

// Loads the default scene (else scene 0; with no scenes, every root node) of a glTF
// file. Everything the renderer reads is validated first, files are read only as
// `limits` allow (gltf/asset_access.h), and the memory the scene will need is counted
// against limits.maxMemory before it is allocated; any problem throws Error whose
// message starts with the file name. Skinned meshes follow their joints and morph
// targets their weights, in the pose `choice` gives; primitives take the materials of its
// variant.
Scene LoadGltf(const std::string& path, const LoadLimits& limits = {}, const SceneChoice& choice = {});

}  // namespace vkpt::internal

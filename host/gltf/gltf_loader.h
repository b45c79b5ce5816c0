// glTF 2.0 (.gltf / .glb) → Scene.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scene/load_limits.h"
#include "scene/scene.h"

namespace vkpt::internal {

// What to render of a file beyond its default scene.
struct SceneChoice {
  std::string variant{};    // a KHR_materials_variants variant, by name or index; "": the primitives' own materials
  std::string animation{};  // an animation, by name or index; "": the nodes' own transforms
  double time = 0.0;        // seconds into the animation (LoadedScene: of its first pose)
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
  // Material `index` replaced, for this pose and every later one.
  void SetMaterial(uint32_t index, const Material& material);

  struct Parts;  // the parsed file, its decoded meshes and rest pose (gltf_loader.cpp)

 private:
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

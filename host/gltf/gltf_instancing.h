// The scene graph flattened (glTF 2.0 spec §3.5): every node of the rendered scene
// with its world transform (TRS or matrix, parent × child), its mesh's triangles —
// morphed by its weights, then moved to world space by that transform or by its skin's
// joints (gltf/posed_primitive.h) — its camera and its light.
#pragma once

#include <cstdint>
#include <vector>

#include "gltf/gltf_meshes.h"
#include "gltf/gltf_skins.h"
#include "gltf/gltf_source.h"
#include "gltf/node_pose.h"
#include "scene/scene.h"

namespace vkpt::internal {

// The roots of the scene to render: the default scene, else scene 0, else every root
// node. `parents` comes from CheckNodeGraph.
std::vector<int> SceneRoots(const GltfSource& src, const std::vector<int>& parents);

// How many times the scene under `roots` instantiates each mesh.
std::vector<uint64_t> MeshInstances(const GltfSource& src, const std::vector<int>& roots);

// What the scene is instantiated in: every node's pose and world transform, and the
// file's skins.
struct ScenePose {
  std::vector<NodePose> nodes;
  std::vector<glm::dmat4> world;
  const std::vector<Skin>& skins;
};

// Adds the world-space triangles, cameras and lights of the scene to `scene`. Iterative: a
// hierarchy thousands of levels deep must not overflow the call stack.
void InstantiateScene(const GltfSource& src, const std::vector<int>& parents, const ScenePose& pose,
                      const std::vector<std::vector<DecodedPrimitive>>& meshes, Scene& scene);

}  // namespace vkpt::internal

// What a GltfAsset keeps of its file to pose it again (gltf_loader.cpp) and to describe
// and edit its nodes, meshes and lights (gltf_edits.cpp).
#pragma once

#include <tiny_gltf.h>

#include <vector>

#include "gltf/gltf_loader.h"
#include "gltf/gltf_meshes.h"
#include "gltf/gltf_skins.h"
#include "gltf/node_pose.h"

namespace vkpt::internal {

struct GltfAsset::Parts {
  tinygltf::Model model;
  Scene scene;
  std::vector<int> parents;                           // CheckNodeGraph's
  std::vector<std::vector<DecodedPrimitive>> meshes;  // decoded, in object space
  std::vector<NodePose> rest;                         // as the file places the nodes
  std::vector<Skin> skins;
  size_t readWarnings = 0;  // the scene's warnings from reading it; each pose adds its own
  bool released = false;    // ReleaseSource() freed the above
};

}  // namespace vkpt::internal

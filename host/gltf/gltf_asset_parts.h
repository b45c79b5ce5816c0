// What a GltfAsset keeps of its file to pose it again (gltf_loader.cpp) and to describe
// and edit its nodes, meshes and lights (gltf_edits.cpp).
#pragma once

#include <tiny_gltf.h>

#include <string>
#include <vector>

#include "gltf/gltf_loader.h"
#include "gltf/gltf_meshes.h"
#include "gltf/gltf_skins.h"
#include "gltf/gltf_source.h"
#include "gltf/node_pose.h"

namespace vkpt::internal {

struct GltfAsset::Parts {
  tinygltf::Model model;
  Scene scene;
  std::vector<int> parents;                           // CheckNodeGraph's
  std::vector<std::vector<DecodedPrimitive>> meshes;  // decoded, in object space
  std::vector<NodePose> rest;                         // as the file places the nodes
  std::vector<Skin> skins;
  MeshDecoding decoding;  // as `meshes` were decoded
  bool textured = false;  // some material has a texture
  // Of scene.memoryCounted: the meshes (ChargeGeometry) and the chosen animation's keyframes.
  uint64_t geometryBytes = 0, animationBytes = 0;
  size_t readWarnings = 0;  // the scene's warnings from reading it; each pose adds its own
  bool released = false;    // ReleaseSource() freed the above
};

// The TEXCOORD set the tangents of a primitive with material `mat` follow
// (gltf_loader.cpp); −1: it needs none.
int TangentUVSet(const Material& mat);

// meshes[mesh] of the file decoded as parts.decoding says, the tangents its primitives'
// materials need generated (MikkTSpace) where the file gives none; DecodeMesh's warnings
// go to `warnings`.
std::vector<DecodedPrimitive> DecodeMeshOf(const GltfSource& src, const GltfAsset::Parts& parts, size_t mesh,
                                           std::vector<std::string>& warnings);

// The primitives of `meshes` given generated tangents.
uint32_t GeneratedTangentPrimitives(const std::vector<std::vector<DecodedPrimitive>>& meshes);

}  // namespace vkpt::internal

// glTF skins (spec §3.7.3): joints and their inverse bind matrices, and the matrices that
// move a skinned vertex — joint world transform × inverse bind matrix, weighted by the
// vertex's JOINTS_n/WEIGHTS_n (linear blend skinning). The skinned mesh's own node
// transform plays no part.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "gltf/gltf_source.h"

namespace vkpt::internal {

struct Skin {
  std::vector<int> joints;               // node indices
  std::vector<glm::dmat4> inverseBinds;  // one per joint; identity where the file gives none
};

// The file's skins, checked: joints in range and distinct, inverse bind matrices a FLOAT
// MAT4 accessor with one finite matrix per joint.
std::vector<Skin> ReadSkins(const GltfSource& src);

// The skin's joint matrices for the nodes' world transforms `world`.
std::vector<glm::dmat4> JointMatrices(const Skin& skin, const std::vector<glm::dmat4>& world);

}  // namespace vkpt::internal

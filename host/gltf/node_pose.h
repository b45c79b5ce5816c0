// Where each node of a glTF file stands (spec §3.5.2–3.5.3): its local transform — a
// matrix, or translation, rotation and scale, which animations replace — and its morph
// target weights; and the world transforms that follow down the hierarchy.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "gltf/gltf_source.h"

namespace vkpt::internal {

struct NodePose {
  std::optional<glm::dmat4> matrix;  // the node's matrix, which excludes the three below
  glm::dvec3 translation{0.0};
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};  // unit
  glm::dvec3 scale{1.0};
  // The node's mesh's morph target weights: the node's, else the mesh's, else zeros;
  // empty when the mesh has no targets.
  std::vector<double> weights;

  glm::dmat4 Local() const;  // the matrix, else T · R · S
};

// The nodes as the file places them, checked: matrices of 16 and TRS vectors of 3 or 4
// finite numbers, rotations that can be made unit, and weights as many as the mesh's
// morph targets.
std::vector<NodePose> RestPoses(const GltfSource& src);

// Every node's world transform, parent × local from the roots down (`parents` from
// CheckNodeGraph), without recursion.
std::vector<glm::dmat4> WorldTransforms(const std::vector<int>& parents, const std::vector<NodePose>& poses);

// The number of morph targets of meshes[mesh], the same for each of its primitives
// (checked).
size_t MorphTargetCount(const GltfSource& src, int mesh);

}  // namespace vkpt::internal

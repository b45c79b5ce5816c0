// A primitive's vertices in world space, moved rigidly by its node's transform (spec
// §3.5.3) or by its skin's joints (§3.7.3, linear blend skinning): positions; normals by
// the inverse transpose; tangents as directions, their sign flipped where the transform
// mirrors; and each triangle's mirroring, which flips its winding back.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gltf/gltf_meshes.h"
#include "gltf/gltf_source.h"

namespace vkpt::internal {

struct PosedPrimitive {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;   // unit, or zero where the transform leaves no direction
  std::vector<glm::vec4> tangents;  // per vertex (TANGENT) or per corner (generated), as the primitive has them
  std::vector<uint8_t> mirrored;    // per triangle
};

// `prim` moved by `world`. `what` names it in errors (a position that leaves float range).
PosedPrimitive PoseRigid(const GltfSource& src, const DecodedPrimitive& prim, const glm::dmat4& world,
                         const std::string& what);

// `prim` moved by the blend of `jointMatrices` its JOINTS_n/WEIGHTS_n give each vertex,
// the weights normalized to sum 1; a vertex whose weights are all zero stays in place,
// and each such vertex is counted in `unweighted`. Joint indices must be in range.
PosedPrimitive PoseSkinned(const GltfSource& src, const DecodedPrimitive& prim,
                           const std::vector<glm::dmat4>& jointMatrices, const std::string& what, size_t& unweighted);

}  // namespace vkpt::internal

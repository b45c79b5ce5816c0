// EXT_mesh_gpu_instancing: a node that draws its mesh once per instance, each placed by
// its TRANSLATION, ROTATION and SCALE in the node's space (the node's world transform
// applies after the instance's).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "gltf/gltf_source.h"

namespace vkpt::internal {

// How many instances nodes[node] draws: its attributes' count with the extension, else 1
// (nothing is decoded; the counts are checked alike).
uint64_t InstanceCount(const GltfSource& src, int node);

// Each instance's transform T · R · S; empty without the extension. The attributes must
// be VEC3 FLOAT (TRANSLATION, SCALE) and VEC4 FLOAT or normalized BYTE/SHORT (ROTATION),
// of one count, with finite values.
std::vector<glm::dmat4> InstanceTransforms(const GltfSource& src, int node);

}  // namespace vkpt::internal

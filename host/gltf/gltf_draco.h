// KHR_draco_mesh_compression: each compressed primitive's bitstream is decoded and its
// indices and attribute accessors pointed at the decoded data in a buffer of their own,
// so the phases after this one read plain glTF.
#pragma once

#include <tiny_gltf.h>

#include <string>

#include "scene/load_limits.h"

namespace vkpt::internal {

// Runs after the bufferViews are checked, before the accessors are; the decoded sizes
// the accessors declare are charged to `budget` before the bitstream is decoded, and
// what it decodes to must match them. Throws Error naming `path` and the primitive.
void DecodeDracoPrimitives(const std::string& path, tinygltf::Model& model, MemoryBudget& budget);

}  // namespace vkpt::internal

// EXT_meshopt_compression: every compressed bufferView is decoded into a buffer of its
// own and pointed at it, so the phases after this one read plain glTF. Its fallback
// buffer (often without data: tinygltf_edits.h) may be read by compressed views only.
#pragma once

#include <tiny_gltf.h>

#include <string>

#include "scene/load_limits.h"

namespace vkpt::internal {

// Runs after tinygltf has read the buffers, before the bufferViews are checked; the
// decoded bytes are charged to `budget` before they are allocated. Throws Error
// naming `path` and the bufferView.
void DecodeMeshoptViews(const std::string& path, tinygltf::Model& model, MemoryBudget& budget);

}  // namespace vkpt::internal

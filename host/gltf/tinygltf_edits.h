// Two kinds of valid compressed glTF that Debian's tinygltf (built without Draco) refuses,
// and the edits of their JSON that let it parse them, undone on the model it returns:
// - KHR_draco_mesh_compression: a primitive's indices accessor has no bufferView (its
//   data is in the bitstream), and tinygltf demands one. It is given bufferViews[0] for
//   the parse and none again after.
// - EXT_meshopt_compression: the fallback buffer may have no uri, which tinygltf takes
//   for a GLB's BIN chunk (or refuses in a .gltf). It is given a one-byte data: uri for
//   the parse and no data after.
#pragma once

#include <tiny_gltf.h>

#include <nlohmann/json.hpp>

#include <vector>

namespace vkpt::internal {

struct TinyGltfEdits {
  std::vector<int> accessorsWithoutBufferView;
  std::vector<int> fallbackBuffersWithoutUri;
  bool Empty() const { return accessorsWithoutBufferView.empty() && fallbackBuffersWithoutUri.empty(); }
};

// Edits `doc` (a schema-checked glTF) in place; returns what it changed.
TinyGltfEdits EditForTinyGltf(nlohmann::json& doc);

// Undoes `edits` on the model tinygltf parsed from the edited JSON.
void UndoTinyGltfEdits(const TinyGltfEdits& edits, tinygltf::Model& model);

}  // namespace vkpt::internal

#include "gltf/tinygltf_edits.h"

namespace vkpt::internal {
namespace {

using nlohmann::json;

json* Member(json& object, const char* key) {
  if (!object.is_object()) return nullptr;
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

bool IsMeshoptFallback(json& buffer) {
  json* ext = Member(buffer, "extensions");
  json* meshopt = ext ? Member(*ext, "EXT_meshopt_compression") : nullptr;
  json* fallback = meshopt ? Member(*meshopt, "fallback") : nullptr;
  return fallback && fallback->is_boolean() && fallback->get<bool>();
}

}  // namespace

TinyGltfEdits EditForTinyGltf(json& doc) {
  TinyGltfEdits edits;
  json* accessors = Member(doc, "accessors");
  json* views = Member(doc, "bufferViews");
  json* meshes = Member(doc, "meshes");
  if (accessors && views && !views->empty() && meshes)
    for (json& mesh : *meshes)
      if (json* prims = Member(mesh, "primitives"))
        for (json& prim : *prims) {
          json* ext = Member(prim, "extensions");
          json* indices = Member(prim, "indices");
          if (!ext || !Member(*ext, "KHR_draco_mesh_compression") || !indices || !indices->is_number_unsigned())
            continue;
          const size_t i = indices->get<size_t>();
          if (i < accessors->size() && (*accessors)[i].is_object() && !Member((*accessors)[i], "bufferView")) {
            (*accessors)[i]["bufferView"] = 0;
            edits.accessorsWithoutBufferView.push_back(int(i));
          }
        }
  if (json* buffers = Member(doc, "buffers"))
    for (size_t i = 0; i < buffers->size(); ++i) {
      json& b = (*buffers)[i];
      if (!IsMeshoptFallback(b) || Member(b, "uri")) continue;
      b["uri"] = "data:application/octet-stream;base64,AA==";
      b["byteLength"] = 1;
      edits.fallbackBuffersWithoutUri.push_back(int(i));
    }
  return edits;
}

void UndoTinyGltfEdits(const TinyGltfEdits& edits, tinygltf::Model& model) {
  for (int i : edits.accessorsWithoutBufferView) model.accessors[i].bufferView = -1;
  for (int i : edits.fallbackBuffersWithoutUri) {
    model.buffers[i].data.clear();
    model.buffers[i].uri.clear();
  }
}

}  // namespace vkpt::internal

#include "gltf/gltf_draco.h"

#include <cstdint>
#include <cstring>
#include <set>
#include <vector>

#include "gltf/draco_decode.h"
#include "gltf/gltf_accessors.h"
#include "gltf/gltf_extension_values.h"
#include "gltf/gltf_source.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

constexpr const char* kExtension = "KHR_draco_mesh_compression";

// Appends `bytes` to `buffer` (4-byte aligned) as a new bufferView; returns its index.
int AppendView(tinygltf::Model& m, int buffer, const std::vector<unsigned char>& bytes) {
  std::vector<unsigned char>& data = m.buffers[buffer].data;
  data.resize((data.size() + 3) / 4 * 4);
  tinygltf::BufferView view;
  view.buffer = buffer;
  view.byteOffset = data.size();
  view.byteLength = bytes.size();
  data.insert(data.end(), bytes.begin(), bytes.end());
  m.bufferViews.push_back(view);
  return int(m.bufferViews.size()) - 1;
}

// The decoded indices as the indices accessor's component type lays them out.
std::vector<unsigned char> PackIndices(const GltfSource& src, const std::vector<uint32_t>& indices, int componentType,
                                       const std::string& what) {
  const int size = ComponentSize(componentType);
  std::vector<unsigned char> out(indices.size() * size_t(size));
  for (size_t i = 0; i < indices.size(); ++i) {
    const uint32_t v = indices[i];
    if (size < 4 && v >> (8 * size))
      src.Fail(what + ": index " + std::to_string(v) + " does not fit the indices accessor's component type");
    std::memcpy(out.data() + i * size, &v, size_t(size));  // little-endian: the low bytes first
  }
  return out;
}

// The attributes the extension decodes: each one's Draco attribute and accessor, appended
// to `wanted` and `targets`. Returns the bytes their accessors hold.
uint64_t DecodedAttributes(const GltfSource& src, const tinygltf::Model& m, const tinygltf::Primitive& prim,
                           const tinygltf::Value& attributes, const std::string& name, const std::string& what,
                           std::vector<DracoAccessor>& wanted, std::vector<int>& targets) {
  uint64_t bytes = 0;
  for (const std::string& attr : attributes.Keys()) {
    const auto it = prim.attributes.find(attr);
    if (it == prim.attributes.end()) src.Fail(what + ".attributes." + attr + " is not an attribute of " + name);
    src.CheckIndex(it->second, m.accessors, name + ".attributes." + attr);
    const tinygltf::Accessor& a = m.accessors[it->second];
    const uint64_t id = ExtensionUnsigned(src, attributes, attr.c_str(), what + ".attributes");
    if (id > UINT32_MAX) src.Fail(what + ".attributes." + attr + " is not a Draco attribute id");
    const int components = ComponentCount(a.type);
    if (components < 1 || components > 4 || ComponentSize(a.componentType) == 0 ||
        a.componentType == TINYGLTF_COMPONENT_TYPE_INT)
      src.Fail(name + ".attributes." + attr + ": accessors[" + std::to_string(it->second) +
               "] is not a SCALAR…VEC4 of a glTF vertex component type");
    wanted.push_back({attr, uint32_t(id), components, a.componentType, a.count});
    targets.push_back(it->second);
    bytes += uint64_t(a.count) * ElementSize(a);
  }
  return bytes;
}

void DecodePrimitive(const GltfSource& src, tinygltf::Model& m, tinygltf::Primitive& prim, const std::string& name,
                     std::set<int>& decodedAccessors, MemoryBudget& budget) {
  const std::string what = name + ".extensions." + kExtension;
  const tinygltf::Value& ext = prim.extensions.at(kExtension);
  if (!ext.IsObject()) src.Fail(what + " is not an object");
  const int viewIndex = ExtensionIndex(src, ext, "bufferView", m.bufferViews, what);
  if (!ext.Has("attributes") || !ext.Get("attributes").IsObject())
    src.Fail(what + ".attributes is missing or not an object");
  if (prim.mode != TINYGLTF_MODE_TRIANGLES) src.Fail(name + ".mode must be TRIANGLES (4) with " + kExtension);
  if (prim.indices < 0) src.Fail(name + " has no indices, which " + kExtension + " needs");
  src.CheckIndex(prim.indices, m.accessors, name + ".indices");
  const tinygltf::Value& attributes = ext.Get("attributes");

  std::vector<int> targets;  // accessors[...] per DracoAccessor, then the indices'
  std::vector<DracoAccessor> wanted;
  uint64_t bytes = DecodedAttributes(src, m, prim, attributes, name, what, wanted, targets);
  const tinygltf::Accessor& ia = m.accessors[prim.indices];
  if (ia.type != TINYGLTF_TYPE_SCALAR || (ia.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                          ia.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                          ia.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
    src.Fail(name + ".indices: accessors[" + std::to_string(prim.indices) +
             "] must be a SCALAR of UNSIGNED_BYTE, SHORT or INT");
  targets.push_back(prim.indices);
  bytes += uint64_t(ia.count) * ElementSize(ia);
  for (int t : targets)
    if (!decodedAccessors.insert(t).second)
      src.Fail(name + ": accessors[" + std::to_string(t) + "] is decoded by another " + kExtension + " primitive too");
  // Draco's own mesh (its attribute arrays, its faces and, for edgebreaker data, a
  // corner table of some 48 bytes per triangle) lives beside the output as it is copied.
  budget.Charge(2 * bytes + 48 * uint64_t(ia.count) / 3, name + " (" + kExtension + ", decoded)");

  const tinygltf::BufferView& view = m.bufferViews[viewIndex];
  const std::vector<unsigned char>& data = m.buffers[view.buffer].data;
  DracoPrimitive decoded;
  try {
    decoded = DecodeDraco({data.data() + view.byteOffset, view.byteLength}, wanted, ia.count);
  } catch (const Error& e) {
    src.Fail(name + ": " + e.what());
  }
  std::vector<unsigned char> indices = PackIndices(src, decoded.indices, ia.componentType, name);
  m.buffers.emplace_back();
  const int buffer = int(m.buffers.size()) - 1;
  decoded.attributes.push_back(std::move(indices));
  for (size_t i = 0; i < targets.size(); ++i) {
    tinygltf::Accessor& a = m.accessors[targets[i]];
    a.bufferView = AppendView(m, buffer, decoded.attributes[i]);
    a.byteOffset = 0;
  }
}

}  // namespace

void DecodeDracoPrimitives(const std::string& path, tinygltf::Model& model, MemoryBudget& budget) {
  const GltfSource src{path, model};
  std::set<int> decodedAccessors;
  for (size_t i = 0; i < model.meshes.size(); ++i)
    for (size_t j = 0; j < model.meshes[i].primitives.size(); ++j) {
      tinygltf::Primitive& prim = model.meshes[i].primitives[j];
      if (prim.extensions.count(kExtension))
        DecodePrimitive(src, model, prim, "meshes[" + std::to_string(i) + "].primitives[" + std::to_string(j) + "]",
                        decodedAccessors, budget);
    }
}

}  // namespace vkpt::internal

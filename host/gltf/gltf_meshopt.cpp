#include "gltf/gltf_meshopt.h"

#include <vector>

#include "gltf/gltf_extension_values.h"
#include "gltf/gltf_source.h"
#include "gltf/meshopt_decode.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

constexpr const char* kExtension = "EXT_meshopt_compression";

bool IsFallback(const tinygltf::Buffer& b) {
  const auto ext = b.extensions.find(kExtension);
  return ext != b.extensions.end() && ext->second.IsObject() && ext->second.Has("fallback") &&
         ext->second.Get("fallback").IsBool() && ext->second.Get("fallback").Get<bool>();
}

// Decodes bufferViews[i] into a new buffer and points the view at it.
void DecodeView(const GltfSource& src, tinygltf::Model& m, size_t i, MemoryBudget& budget) {
  tinygltf::BufferView& view = m.bufferViews[i];
  const std::string name = "bufferViews[" + std::to_string(i) + "]";
  const std::string what = name + ".extensions." + kExtension;
  const tinygltf::Value& ext = view.extensions.at(kExtension);
  if (!ext.IsObject()) src.Fail(what + " is not an object");
  const int buffer = ExtensionIndex(src, ext, "buffer", m.buffers, what);
  const uint64_t offset = ExtensionUnsigned(src, ext, "byteOffset", what, 0);
  const uint64_t length = ExtensionUnsigned(src, ext, "byteLength", what);
  MeshoptStream s;
  s.byteStride = ExtensionUnsigned(src, ext, "byteStride", what);
  s.count = ExtensionUnsigned(src, ext, "count", what);
  s.mode = ExtensionString(src, ext, "mode", what, "");
  s.filter = ExtensionString(src, ext, "filter", what, "NONE");
  if (std::string problem = CheckMeshoptStream(s); !problem.empty()) src.Fail(what + ": " + problem);
  const std::vector<unsigned char>& data = m.buffers[buffer].data;
  if (IsFallback(m.buffers[buffer]))
    src.Fail(what + ".buffer is buffers[" + std::to_string(buffer) + "], the fallback, not the compressed data");
  if (offset > data.size() || length > data.size() - offset)
    src.Fail(what + " (offset " + std::to_string(offset) + ", length " + std::to_string(length) +
             ") runs past the end of buffers[" + std::to_string(buffer) + "] (" + std::to_string(data.size()) +
             " bytes)");
  // count ≤ 2^53 and byteStride ≤ 256: the product does not overflow.
  const uint64_t decoded = s.count * s.byteStride;
  if (decoded != view.byteLength)
    src.Fail(what + ": count × byteStride = " + std::to_string(decoded) + " bytes, but " + name + ".byteLength is " +
             std::to_string(view.byteLength));
  if (s.mode == "ATTRIBUTES" && view.byteStride != 0 && view.byteStride != s.byteStride)
    src.Fail(what + ".byteStride " + std::to_string(s.byteStride) + " differs from " + name + ".byteStride " +
             std::to_string(view.byteStride));
  budget.Charge(decoded, name + " (" + kExtension + ", decoded)");
  tinygltf::Buffer out;
  out.data.resize(size_t(decoded));
  try {
    DecodeMeshoptStream({data.data() + offset, size_t(length)}, s, out.data);
  } catch (const Error& e) {
    src.Fail(name + ": " + e.what());
  }
  m.buffers.push_back(std::move(out));
  view.buffer = int(m.buffers.size()) - 1;
  view.byteOffset = 0;
}

}  // namespace

void DecodeMeshoptViews(const std::string& path, tinygltf::Model& model, MemoryBudget& budget) {
  const GltfSource src{path, model};
  const size_t views = model.bufferViews.size();
  for (size_t i = 0; i < views; ++i)
    if (model.bufferViews[i].extensions.count(kExtension)) DecodeView(src, model, i, budget);
  for (size_t i = 0; i < views; ++i) {
    const int b = model.bufferViews[i].buffer;
    if (b >= 0 && size_t(b) < model.buffers.size() && IsFallback(model.buffers[b]) && model.buffers[b].data.empty())
      src.Fail("bufferViews[" + std::to_string(i) + "] reads buffers[" + std::to_string(b) + "], " + kExtension +
               "'s fallback, which holds no data; only compressed bufferViews may refer to it");
  }
}

}  // namespace vkpt::internal

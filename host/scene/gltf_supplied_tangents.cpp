#include "scene/gltf_supplied_tangents.h"

#include <tiny_gltf.h>

#include "scene/gltf_accessors.h"
#include "scene/gltf_meshes.h"
#include "scene/gltf_source.h"
#include "scene/gltf_validate.h"
#include "util/error.h"

namespace vkpt {
namespace {

// Images stay undecoded: only geometry is wanted.
bool SkipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

tinygltf::Model Parse(const std::string& path) {
  tinygltf::TinyGLTF gltf;
  gltf.SetImageLoader(SkipImage, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  const bool binary = path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0;
  const bool ok =
      binary ? gltf.LoadBinaryFromFile(&model, &err, &warn, path) : gltf.LoadASCIIFromFile(&model, &err, &warn, path);
  if (!ok) throw Error(path + ": " + (err.empty() ? std::string("malformed glTF") : err));
  return model;
}

// TANGENT of `prim` as VEC4s, one per vertex, or empty if it has none.
std::vector<glm::vec4> ReadTangents(const GltfSource& src, const tinygltf::Primitive& prim, size_t vertexCount,
                                    const std::string& name) {
  auto it = prim.attributes.find("TANGENT");
  if (it == prim.attributes.end()) return {};
  const tinygltf::Accessor& a = src.m.accessors[it->second];
  if (a.type != TINYGLTF_TYPE_VEC4 || a.count != vertexCount)
    src.Fail(name + ".attributes.TANGENT must be a VEC4 with one element per vertex");
  std::vector<double> raw = ReadAccessor(src, it->second);
  std::vector<glm::vec4> out(vertexCount);
  for (size_t v = 0; v < vertexCount; ++v)
    out[v] = glm::vec4(float(raw[4 * v]), float(raw[4 * v + 1]), float(raw[4 * v + 2]), float(raw[4 * v + 3]));
  return out;
}

}  // namespace

std::vector<SuppliedTangents> ReadSuppliedTangents(const std::string& path) {
  const tinygltf::Model model = Parse(path);
  const GltfSource src{path, model};
  CheckAsset(src);
  CheckBufferViews(src);
  for (size_t i = 0; i < model.accessors.size(); ++i) CheckAccessor(src, int(i));
  std::vector<SuppliedTangents> out;
  std::vector<std::string> warnings;
  for (size_t m = 0; m < model.meshes.size(); ++m) {
    std::vector<DecodedPrimitive> decoded = DecodeMesh(src, int(m), 0, true, warnings);
    // DecodeMesh skips points and lines: walk the triangle primitives alongside.
    size_t d = 0;
    for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
      const tinygltf::Primitive& prim = model.meshes[m].primitives[p];
      if (prim.mode < TINYGLTF_MODE_TRIANGLES) continue;
      DecodedPrimitive& dp = decoded[d++];
      const std::string name = "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) + "]";
      int set = 0;
      if (prim.material >= 0 && size_t(prim.material) < model.materials.size())
        set = model.materials[prim.material].normalTexture.texCoord == 1 ? 1 : 0;
      std::vector<glm::vec4> tangents = ReadTangents(src, prim, dp.positions.size(), name);
      SuppliedTangents s{name,
                         std::move(dp.positions),
                         std::move(dp.normals),
                         std::move(dp.uvs[set]),
                         std::move(dp.indices),
                         std::move(tangents)};
      if (!s.tangents.empty() && !s.normals.empty() && !s.uvs.empty()) out.push_back(std::move(s));
    }
  }
  return out;
}

}  // namespace vkpt

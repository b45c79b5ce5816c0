#include "gltf/gltf_validate.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "gltf/gltf_accessors.h"

namespace vkpt::internal {
namespace {

// Extensions vkpt renders every property of.
const std::set<std::string> kSupportedRequiredExtensions = {
    "KHR_lights_punctual",        "KHR_materials_anisotropy",
    "KHR_materials_clearcoat",    "KHR_materials_diffuse_transmission",
    "KHR_materials_dispersion",   "KHR_materials_emissive_strength",
    "KHR_materials_ior",          "KHR_materials_iridescence",
    "KHR_materials_sheen",        "KHR_materials_specular",
    "KHR_materials_transmission", "KHR_materials_unlit",
    "KHR_materials_variants",     "KHR_materials_volume",
    "KHR_mesh_quantization",      "KHR_texture_transform",
    "KHR_draco_mesh_compression", "EXT_meshopt_compression",
    "EXT_mesh_gpu_instancing",    "EXT_texture_webp"};

void CheckTextureRef(const GltfSource& src, int index, const std::string& what) {
  if (index != -1) src.CheckIndex(index, src.m.textures, what);
}

}  // namespace

bool IsSupportedExtension(const std::string& name) { return kSupportedRequiredExtensions.count(name) > 0; }

void CheckAsset(const GltfSource& src) {
  const std::string& v = src.m.asset.version;
  if (v.empty()) src.Fail("asset.version is missing");
  if (v.substr(0, v.find('.')) != "2") src.Fail("asset.version is \"" + v + "\"; vkpt reads glTF 2.x only");
  // A required KHR_texture_basisu is refused texture by texture, where no fallback image
  // is there to stand in for the KTX2 one (gltf_textures.cpp).
  for (const std::string& ext : src.m.extensionsRequired)
    if (!IsSupportedExtension(ext) && ext != "KHR_texture_basisu")
      src.Fail("the file requires extension " + ext + ", which vkpt does not support");
}

void CheckBufferViews(const GltfSource& src) {
  for (size_t i = 0; i < src.m.bufferViews.size(); ++i) {
    const tinygltf::BufferView& bv = src.m.bufferViews[i];
    std::string name = "bufferViews[" + std::to_string(i) + "]";
    src.CheckIndex(bv.buffer, src.m.buffers, name + ".buffer");
    size_t size = src.m.buffers[bv.buffer].data.size();
    if (bv.byteLength == 0) src.Fail(name + ".byteLength is 0");
    if (bv.byteOffset > size || bv.byteLength > size - bv.byteOffset)
      src.Fail(name + " (offset " + std::to_string(bv.byteOffset) + ", length " + std::to_string(bv.byteLength) +
               ") runs past the end of buffer " + std::to_string(bv.buffer) + " (" + std::to_string(size) + " bytes)");
    if (bv.byteStride != 0 && (bv.byteStride < 4 || bv.byteStride > 252 || bv.byteStride % 4))
      src.Fail(name + ".byteStride is " + std::to_string(bv.byteStride) + "; it must be a multiple of 4 in [4, 252]");
  }
}

void CheckTexturesAndMaterials(const GltfSource& src) {
  for (size_t i = 0; i < src.m.textures.size(); ++i) {
    const tinygltf::Texture& t = src.m.textures[i];
    std::string name = "textures[" + std::to_string(i) + "]";
    if (t.source != -1) src.CheckIndex(t.source, src.m.images, name + ".source");
    if (t.sampler != -1) src.CheckIndex(t.sampler, src.m.samplers, name + ".sampler");
  }
  for (size_t i = 0; i < src.m.images.size(); ++i) {
    const tinygltf::Image& im = src.m.images[i];
    if (im.bufferView != -1)
      src.CheckIndex(im.bufferView, src.m.bufferViews, "images[" + std::to_string(i) + "].bufferView");
  }
  for (size_t i = 0; i < src.m.materials.size(); ++i) {
    const tinygltf::Material& mat = src.m.materials[i];
    std::string name = "materials[" + std::to_string(i) + "]";
    CheckTextureRef(src, mat.pbrMetallicRoughness.baseColorTexture.index,
                    name + ".pbrMetallicRoughness.baseColorTexture.index");
    CheckTextureRef(src, mat.pbrMetallicRoughness.metallicRoughnessTexture.index,
                    name + ".pbrMetallicRoughness.metallicRoughnessTexture.index");
    CheckTextureRef(src, mat.normalTexture.index, name + ".normalTexture.index");
    CheckTextureRef(src, mat.occlusionTexture.index, name + ".occlusionTexture.index");
    CheckTextureRef(src, mat.emissiveTexture.index, name + ".emissiveTexture.index");
  }
}

void CheckCameras(const GltfSource& src) {
  for (size_t i = 0; i < src.m.cameras.size(); ++i) {
    const tinygltf::Camera& c = src.m.cameras[i];
    std::string name = "cameras[" + std::to_string(i) + "]";
    if (c.type == "perspective") {
      const auto& p = c.perspective;
      if (!std::isfinite(p.yfov) || p.yfov <= 0.0 || p.yfov >= 3.14159)
        src.Fail(name + ".perspective.yfov must be in (0, π)");
      if (!std::isfinite(p.aspectRatio) || p.aspectRatio < 0.0) src.Fail(name + ".perspective.aspectRatio must be > 0");
    } else if (c.type == "orthographic") {
      const auto& o = c.orthographic;
      if (!std::isfinite(o.xmag) || !std::isfinite(o.ymag) || o.xmag == 0.0 || o.ymag == 0.0)
        src.Fail(name + ".orthographic xmag/ymag must be finite and non-zero");
    } else {
      src.Fail(name + ".type \"" + c.type + "\" is neither perspective nor orthographic");
    }
  }
}

std::vector<int> CheckNodeGraph(const GltfSource& src) {
  std::vector<int> parent(src.m.nodes.size(), -1);
  for (size_t i = 0; i < src.m.nodes.size(); ++i) {
    for (int c : src.m.nodes[i].children) {
      src.CheckIndex(c, src.m.nodes, "nodes[" + std::to_string(i) + "].children");
      if (parent[c] != -1 || c == int(i))
        src.Fail("nodes[" + std::to_string(c) +
                 "] has more than one parent or is its own child (node graph must be a tree)");
      parent[c] = int(i);
    }
  }
  std::vector<int> roots;
  for (size_t i = 0; i < src.m.nodes.size(); ++i)
    if (parent[i] == -1) roots.push_back(int(i));
  // With at most one parent each, the nodes reachable from the roots form a forest; a
  // node not reached lies on a cycle (its parent chain never ends). Linear time.
  std::vector<char> reached(src.m.nodes.size(), 0);
  std::vector<int> work = roots;
  while (!work.empty()) {
    int n = work.back();
    work.pop_back();
    reached[n] = 1;
    for (int c : src.m.nodes[n].children) work.push_back(c);
  }
  for (size_t i = 0; i < src.m.nodes.size(); ++i)
    if (!reached[i]) src.Fail("nodes[" + std::to_string(i) + "] is part of a cycle in the node hierarchy");
  return parent;
}

namespace {

// NORMAL, TANGENT: FLOAT, or with KHR_mesh_quantization also normalized BYTE or SHORT.
void CheckDirectionAttribute(const GltfSource& src, const tinygltf::Primitive& prim, const std::string& name,
                             const char* attr, int type, const char* typeName, bool quantized) {
  auto it = prim.attributes.find(attr);
  if (it == prim.attributes.end()) return;
  const tinygltf::Accessor& a = src.m.accessors[it->second];
  const bool snorm = a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
                                      a.componentType == TINYGLTF_COMPONENT_TYPE_SHORT);
  if (a.type != type || !(a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || (quantized && snorm)))
    src.Fail(name + ".attributes." + attr + " (accessors[" + std::to_string(it->second) + "]) must be a FLOAT " +
             typeName + " accessor" +
             (quantized ? std::string(" or a normalized BYTE/SHORT ") + typeName + " one" : ""));
}

// JOINTS_n: unsigned byte or short VEC4; WEIGHTS_n: VEC4 of FLOAT or normalized unsigned
// byte or short (spec §3.7.3.1).
void CheckSkinAttributes(const GltfSource& src, const tinygltf::Primitive& prim, const std::string& name) {
  for (const auto& [attr, acc] : prim.attributes) {
    const tinygltf::Accessor& a = src.m.accessors[acc];
    const bool small = a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                       a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    const std::string what = name + ".attributes." + attr + " (accessors[" + std::to_string(acc) + "])";
    if (attr.starts_with("JOINTS_") && (a.type != TINYGLTF_TYPE_VEC4 || !small || a.normalized))
      src.Fail(what + " must be an UNSIGNED_BYTE or UNSIGNED_SHORT VEC4 accessor");
    if (attr.starts_with("WEIGHTS_") &&
        (a.type != TINYGLTF_TYPE_VEC4 ||
         !(a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || (small && a.normalized))))
      src.Fail(what + " must be a VEC4 accessor of FLOAT or normalized UNSIGNED_BYTE/UNSIGNED_SHORT");
  }
}

// Morph targets' POSITION, NORMAL and TANGENT: VEC3 of FLOAT, or with
// KHR_mesh_quantization of (normalized) BYTE or SHORT; as many as the positions.
void CheckTargets(const GltfSource& src, const tinygltf::Primitive& prim, const std::string& name, bool quantized,
                  size_t vertices) {
  for (size_t t = 0; t < prim.targets.size(); ++t)
    for (const auto& [attr, acc] : prim.targets[t]) {
      src.CheckIndex(acc, src.m.accessors, name + ".targets[" + std::to_string(t) + "]." + attr);
      if (attr != "POSITION" && attr != "NORMAL" && attr != "TANGENT") continue;
      const tinygltf::Accessor& a = src.m.accessors[acc];
      const std::string what =
          name + ".targets[" + std::to_string(t) + "]." + attr + " (accessors[" + std::to_string(acc) + "])";
      const bool signedSmall =
          a.componentType == TINYGLTF_COMPONENT_TYPE_BYTE || a.componentType == TINYGLTF_COMPONENT_TYPE_SHORT;
      if (a.type != TINYGLTF_TYPE_VEC3 ||
          !(a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || (quantized && signedSmall)))
        src.Fail(what + " must be a FLOAT VEC3 accessor" +
                 (quantized ? std::string(" or a (normalized) BYTE/SHORT VEC3 one") : ""));
      if (a.count != vertices)
        src.Fail(what + " has " + std::to_string(a.count) + " elements but POSITION has " + std::to_string(vertices));
    }
}

}  // namespace

void CheckPrimitive(const GltfSource& src, const tinygltf::Primitive& prim, const std::string& name) {
  const bool quantized =
      std::count(src.m.extensionsUsed.begin(), src.m.extensionsUsed.end(), "KHR_mesh_quantization") > 0;
  if (prim.mode < TINYGLTF_MODE_POINTS || prim.mode > TINYGLTF_MODE_TRIANGLE_FAN)
    src.Fail(name + ".mode " + std::to_string(prim.mode) + " is not valid");
  if (prim.material != -1) src.CheckIndex(prim.material, src.m.materials, name + ".material");
  auto pos = prim.attributes.find("POSITION");
  if (pos == prim.attributes.end()) src.Fail(name + " has no POSITION attribute");
  for (const auto& [attr, acc] : prim.attributes) src.CheckIndex(acc, src.m.accessors, name + ".attributes." + attr);
  const tinygltf::Accessor& pa = src.m.accessors[pos->second];
  CheckTargets(src, prim, name, quantized, pa.count);
  CheckSkinAttributes(src, prim, name);
  std::string pan = "accessors[" + std::to_string(pos->second) + "]";
  if (pa.type != TINYGLTF_TYPE_VEC3 || (pa.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !quantized))
    src.Fail(name + ".attributes.POSITION (" + pan + ") must be a FLOAT VEC3 accessor");
  CheckDirectionAttribute(src, prim, name, "NORMAL", TINYGLTF_TYPE_VEC3, "VEC3", quantized);
  CheckDirectionAttribute(src, prim, name, "TANGENT", TINYGLTF_TYPE_VEC4, "VEC4", quantized);
  if (auto col = prim.attributes.find("COLOR_0"); col != prim.attributes.end()) {
    const tinygltf::Accessor& ca = src.m.accessors[col->second];
    const bool unorm = ca.normalized && (ca.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                         ca.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    if ((ca.type != TINYGLTF_TYPE_VEC3 && ca.type != TINYGLTF_TYPE_VEC4) ||
        !(ca.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || unorm))
      src.Fail(name + ".attributes.COLOR_0 (accessors[" + std::to_string(col->second) +
               "]) must be a VEC3 or VEC4 accessor of FLOAT or normalized UNSIGNED_BYTE/UNSIGNED_SHORT");
  }
  // TEXCOORD_n: FLOAT or normalized UNSIGNED_BYTE/SHORT VEC2 (spec §3.7.2.1); with
  // KHR_mesh_quantization any integer type, normalized or not.
  for (const char* attr : {"TEXCOORD_0", "TEXCOORD_1"}) {
    auto tc = prim.attributes.find(attr);
    if (tc == prim.attributes.end()) continue;
    const tinygltf::Accessor& ta = src.m.accessors[tc->second];
    const bool unorm = ta.normalized && (ta.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                         ta.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    const bool integer = ta.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && ComponentSize(ta.componentType) <= 2;
    if (ta.type != TINYGLTF_TYPE_VEC2 ||
        !(ta.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || unorm || (quantized && integer)))
      src.Fail(name + ".attributes." + attr + " (accessors[" + std::to_string(tc->second) +
               "]) must be a VEC2 accessor of FLOAT or normalized UNSIGNED_BYTE/UNSIGNED_SHORT" +
               (quantized ? " or, with KHR_mesh_quantization, of (normalized) BYTE/SHORT" : ""));
  }
  for (const auto& [attr, acc] : prim.attributes)
    if (src.m.accessors[acc].count != pa.count)
      src.Fail(name + ".attributes." + attr + " (accessors[" + std::to_string(acc) + "]) has " +
               std::to_string(src.m.accessors[acc].count) + " elements but POSITION has " + std::to_string(pa.count));
}

}  // namespace vkpt::internal

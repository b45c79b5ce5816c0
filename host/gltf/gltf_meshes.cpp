#include "gltf/gltf_meshes.h"

#include <algorithm>
#include <cmath>

#include "gltf/gltf_accessors.h"
#include "gltf/gltf_validate.h"
#include "gltf/gltf_variants.h"
#include "scene/tangent_space.h"

namespace vkpt::internal {
namespace {

// Index list of a primitive converted to a triangle list.
std::vector<uint32_t> TriangleList(const GltfSource& src, const tinygltf::Primitive& prim, size_t vertexCount,
                                   const std::string& name) {
  std::vector<uint32_t> idx;
  if (prim.indices >= 0) {
    src.CheckIndex(prim.indices, src.m.accessors, name + ".indices");
    const tinygltf::Accessor& a = src.m.accessors[prim.indices];
    std::string an = "accessors[" + std::to_string(prim.indices) + "]";
    if (a.type != TINYGLTF_TYPE_SCALAR || a.normalized ||
        (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
         a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
         a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
      src.Fail(name + ".indices (" + an + ") must be unsigned byte/short/int SCALAR");
    // The all-ones value is reserved for primitive restart, which glTF forbids.
    const double restart = std::pow(2.0, 8.0 * ComponentSize(a.componentType)) - 1.0;
    std::vector<double> raw = ReadAccessor(src, prim.indices);
    idx.reserve(raw.size());
    for (size_t k = 0; k < raw.size(); ++k) {
      if (raw[k] == restart)
        src.Fail(name + ".indices (" + an + ") element " + std::to_string(k) + " is the primitive-restart value " +
                 std::to_string((unsigned long long)restart) + ", which glTF forbids");
      if (raw[k] >= double(vertexCount))
        src.Fail(name + ".indices (" + an + ") element " + std::to_string(k) + " is " +
                 std::to_string((unsigned long long)raw[k]) + ", but the primitive has only " +
                 std::to_string(vertexCount) + " vertices");
      idx.push_back(uint32_t(raw[k]));
    }
  } else {
    idx.resize(vertexCount);
    for (size_t k = 0; k < vertexCount; ++k) idx[k] = uint32_t(k);
  }
  std::vector<uint32_t> tris;
  switch (prim.mode) {
    case TINYGLTF_MODE_TRIANGLES:
      if (idx.size() % 3)
        src.Fail(name + " has " + std::to_string(idx.size()) + " triangle-list indices, which is not a multiple of 3");
      return idx;
    case TINYGLTF_MODE_TRIANGLE_STRIP:
      // Every other triangle swaps two vertices to keep the strip's winding.
      for (size_t k = 2; k < idx.size(); ++k) {
        bool odd = k % 2;
        tris.insert(tris.end(), {idx[k - 2 + odd], idx[k - 1 - odd], idx[k]});
      }
      return tris;
    case TINYGLTF_MODE_TRIANGLE_FAN:
      for (size_t k = 2; k < idx.size(); ++k) tris.insert(tris.end(), {idx[k - 1], idx[k], idx[0]});
      return tris;
    default: return {};
  }
}

// The elements of a checked VEC3 attribute (`attr`: "POSITION", "NORMAL") as floats.
// Components beyond ±1e30 count as non-finite too: a node transform could take them
// past float range unnoticed.
std::vector<glm::vec3> ReadFiniteVec3(const GltfSource& src, int accessor, const std::string& name,
                                      const std::string& attr, const char* noun) {
  std::vector<double> raw = ReadAccessor(src, accessor);
  std::vector<glm::vec3> out(raw.size() / 3);
  for (size_t v = 0; v < out.size(); ++v) {
    for (int c = 0; c < 3; ++c) {
      double x = raw[v * 3 + c];
      if (!std::isfinite(x) || std::abs(x) > 1e30)
        src.Fail(name + ".attributes." + attr + " (accessors[" + std::to_string(accessor) + "]) element " +
                 std::to_string(v) + " is not a finite " + noun);
      out[v][c] = float(x);
    }
  }
  return out;
}

// COLOR_0 as linear RGBA, alpha 1 for a VEC3 accessor. Normalized integers are in [0, 1]
// by construction; floats outside it are clamped (with a warning), as a base colour
// factor above 1 would create energy.
std::vector<glm::vec4> ReadColors(const GltfSource& src, int accessor, const std::string& name,
                                  std::vector<std::string>& warnings) {
  const int n = ComponentCount(src.m.accessors[accessor].type);
  std::vector<double> raw = ReadAccessor(src, accessor);
  std::vector<glm::vec4> out(raw.size() / n, glm::vec4(1.0f));
  size_t clamped = 0;
  for (size_t v = 0; v < out.size(); ++v)
    for (int c = 0; c < n; ++c) {
      double x = raw[v * n + c];
      if (!std::isfinite(x))
        src.Fail(name + ".attributes.COLOR_0 (accessors[" + std::to_string(accessor) + "]) element " +
                 std::to_string(v) + " is not a finite colour");
      clamped += x < 0.0 || x > 1.0;
      out[v][c] = float(std::clamp(x, 0.0, 1.0));
    }
  if (clamped)
    warnings.push_back(name + ".attributes.COLOR_0: " + std::to_string(clamped) +
                       " component(s) outside [0, 1] clamped");
  return out;
}

// The elements of a checked N-component attribute (TEXCOORD_n, TANGENT) as floats, each
// finite (normalized integers already mapped to [0, 1] or [-1, 1]).
template <int N>
std::vector<glm::vec<N, float>> ReadFinite(const GltfSource& src, int accessor, const std::string& name,
                                           const char* attr, const char* noun) {
  std::vector<double> raw = ReadAccessor(src, accessor);
  std::vector<glm::vec<N, float>> out(raw.size() / N);
  for (size_t v = 0; v < out.size(); ++v)
    for (int c = 0; c < N; ++c) {
      const float x = float(raw[v * N + c]);
      if (!std::isfinite(x))
        src.Fail(name + ".attributes." + attr + " (accessors[" + std::to_string(accessor) + "]) element " +
                 std::to_string(v) + " is not a finite " + noun);
      out[v][c] = x;
    }
  return out;
}

// A primitive's morph targets (spec §3.7.2.2): POSITION, NORMAL and TANGENT
// displacements, each finite; NORMAL and TANGENT only where the primitive keeps the
// attribute they displace.
std::vector<MorphTarget> ReadTargets(const GltfSource& src, const tinygltf::Primitive& prim,
                                     const DecodedPrimitive& out, const std::string& name) {
  std::vector<MorphTarget> targets(prim.targets.size());
  for (size_t t = 0; t < targets.size(); ++t) {
    const std::string tn = name + ".targets[" + std::to_string(t) + "]";
    for (const auto& [attr, accessor] : prim.targets[t]) {
      std::vector<glm::vec3>* delta = attr == "POSITION"                           ? &targets[t].positions
                                      : attr == "NORMAL" && !out.normals.empty()   ? &targets[t].normals
                                      : attr == "TANGENT" && !out.tangents.empty() ? &targets[t].tangents
                                                                                   : nullptr;
      if (delta) *delta = ReadFinite<3>(src, accessor, tn, attr.c_str(), "displacement");
    }
  }
  return targets;
}

// JOINTS_n and WEIGHTS_n, each set present as a pair or not at all.
void ReadSkinAttributes(const GltfSource& src, const tinygltf::Primitive& prim, const std::string& name,
                        DecodedPrimitive& out) {
  for (int set = 0; set < 2; ++set) {
    const std::string joints = "JOINTS_" + std::to_string(set), weights = "WEIGHTS_" + std::to_string(set);
    auto j = prim.attributes.find(joints), w = prim.attributes.find(weights);
    if (j == prim.attributes.end() && w == prim.attributes.end()) continue;
    if (j == prim.attributes.end() || w == prim.attributes.end())
      src.Fail(name + " has one of " + joints + " and " + weights + " without the other");
    for (const glm::vec4& v : ReadFinite<4>(src, j->second, name, joints.c_str(), "joint index"))
      out.joints[set].push_back(glm::u16vec4(v));
    out.weights[set] = ReadFinite<4>(src, w->second, name, weights.c_str(), "weight");
    for (size_t v = 0; v < out.weights[set].size(); ++v)
      if (glm::any(glm::lessThan(out.weights[set][v], glm::vec4(0.0f))))
        src.Fail(name + ".attributes." + weights + " element " + std::to_string(v) + " has a negative weight");
  }
}

}  // namespace

std::vector<DecodedPrimitive> DecodeMesh(const GltfSource& src, int meshIndex, const MeshDecoding& d,
                                         std::vector<std::string>& warnings) {
  std::vector<DecodedPrimitive> decoded;
  const tinygltf::Mesh& mesh = src.m.meshes[meshIndex];
  for (size_t p = 0; p < mesh.primitives.size(); ++p) {
    const tinygltf::Primitive& prim = mesh.primitives[p];
    std::string name = "meshes[" + std::to_string(meshIndex) + "].primitives[" + std::to_string(p) + "]";
    CheckPrimitive(src, prim, name);
    if (prim.mode < TINYGLTF_MODE_TRIANGLES) {
      warnings.push_back(name + ": points/lines primitive skipped (only triangles are rendered)");
      continue;
    }
    DecodedPrimitive out;
    out.positions = ReadFiniteVec3(src, prim.attributes.at("POSITION"), name, "POSITION", "position");
    // Not necessarily unit length (the spec asks for it; files do not always comply):
    // the instancer normalizes them after the transform anyway.
    if (auto nrm = prim.attributes.find("NORMAL"); nrm != prim.attributes.end())
      out.normals = ReadFiniteVec3(src, nrm->second, name, "NORMAL", "normal");
    if (auto col = prim.attributes.find("COLOR_0"); col != prim.attributes.end())
      out.colors = ReadColors(src, col->second, name, warnings);
    for (int set = 0; set < 2 && d.withUVs; ++set) {
      const char* attr = set == 0 ? "TEXCOORD_0" : "TEXCOORD_1";
      if (auto tc = prim.attributes.find(attr); tc != prim.attributes.end())
        out.uvs[set] = ReadFinite<2>(src, tc->second, name, attr, "texture coordinate");
    }
    if (auto tan = prim.attributes.find("TANGENT"); d.withTangents && tan != prim.attributes.end()) {
      // xyz as given (the instancer normalizes after the transform), w reduced to its
      // sign (the spec asks for ±1).
      out.tangents = ReadFinite<4>(src, tan->second, name, "TANGENT", "tangent");
      for (glm::vec4& t : out.tangents) t.w = t.w < 0.0f ? -1.0f : 1.0f;
    }
    out.targets = ReadTargets(src, prim, out, name);
    if (d.withSkins) ReadSkinAttributes(src, prim, name, out);
    out.indices = TriangleList(src, prim, out.positions.size(), name);
    const int variantMaterial = VariantMaterial(src, prim, d.variant, d.variantCount, name);
    out.material = variantMaterial >= 0 ? uint32_t(variantMaterial)
                                        : (prim.material >= 0 ? uint32_t(prim.material) : d.defaultMaterial);
    decoded.push_back(std::move(out));
  }
  return decoded;
}

bool GenerateMissingTangents(DecodedPrimitive& prim, uint32_t uvSet) {
  if (!prim.tangents.empty() || !prim.cornerTangents.empty() || uvSet > 1 || prim.uvs[uvSet].empty()) return false;
  std::vector<glm::vec3> normals = prim.normals;
  if (normals.empty()) {
    normals.assign(prim.positions.size(), glm::vec3(0.0f));
    for (size_t k = 0; k + 2 < prim.indices.size(); k += 3) {
      const uint32_t i0 = prim.indices[k], i1 = prim.indices[k + 1], i2 = prim.indices[k + 2];
      const glm::vec3 face =
          glm::cross(prim.positions[i1] - prim.positions[i0], prim.positions[i2] - prim.positions[i0]);
      for (uint32_t i : {i0, i1, i2}) normals[i] += face;
    }
    for (glm::vec3& n : normals)
      if (glm::dot(n, n) > 0.0f) n = glm::normalize(n);
  }
  prim.cornerTangents = GenerateCornerTangents(prim.positions, normals, prim.uvs[uvSet], prim.indices);
  prim.generatedTangentSet = int(uvSet);
  return true;
}

DecodedPrimitive Morphed(const DecodedPrimitive& prim, const std::vector<double>& weights) {
  DecodedPrimitive out = prim;
  for (size_t t = 0; t < prim.targets.size(); ++t) {
    const float w = float(weights[t]);
    if (w == 0.0f) continue;
    const MorphTarget& target = prim.targets[t];
    for (size_t v = 0; v < target.positions.size(); ++v) out.positions[v] += w * target.positions[v];
    for (size_t v = 0; v < target.normals.size(); ++v) out.normals[v] += w * target.normals[v];
    for (size_t v = 0; v < target.tangents.size(); ++v) out.tangents[v] += glm::vec4(w * target.tangents[v], 0.0f);
  }
  // Tangents generated from the base shape follow the displaced one.
  if (prim.generatedTangentSet >= 0) {
    out.cornerTangents.clear();
    GenerateMissingTangents(out, uint32_t(prim.generatedTangentSet));
  }
  return out;
}

uint64_t TriangleCount(const GltfSource& src, const tinygltf::Primitive& prim) {
  auto pos = prim.attributes.find("POSITION");
  size_t n = prim.indices >= 0 && size_t(prim.indices) < src.m.accessors.size() ? src.m.accessors[prim.indices].count
             : pos != prim.attributes.end() && pos->second >= 0 && size_t(pos->second) < src.m.accessors.size()
                 ? src.m.accessors[pos->second].count
                 : 0;
  if (prim.mode == TINYGLTF_MODE_TRIANGLES) return n / 3;
  if (prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP || prim.mode == TINYGLTF_MODE_TRIANGLE_FAN) return n > 2 ? n - 2 : 0;
  return 0;
}

}  // namespace vkpt::internal

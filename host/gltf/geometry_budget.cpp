#include "gltf/geometry_budget.h"

#include <algorithm>
#include <string>

#include "gltf/gltf_accessors.h"
#include "gltf/gltf_meshes.h"

namespace vkpt::internal {
namespace {

// Host memory per triangle of the instanced scene, from the loader's arrays through the
// BVH builds (both trees with --splits auto) to the renderer's arrays and their device
// copies: up to ~490 bytes measured on 1 M triangles with vertex normals
// (docs/design-notes.md), with a margin.
constexpr uint64_t kBytesPerTriangle = 560;
// And per triangle with COLOR_0: the Scene's VertexColors (48 bytes), the packed
// TriangleColors (32) and their staging and device copies (32 each).
constexpr uint64_t kBytesPerColoredTriangle = 144;
// And per triangle with textures: the Scene's VertexUVs (48 bytes), the packed TriangleUVs
// (48) and their staging and device copies (48 each).
constexpr uint64_t kBytesPerTexturedTriangle = 192;
// And per triangle with normal maps: the Scene's VertexTangents (48 bytes), the packed
// TriangleTangents (16) and their staging and device copies (16 each), and generated
// tangents' corners (48, and 48 more while an instance transforms them).
constexpr uint64_t kBytesPerTangentTriangle = 192;
// Decoding an accessor holds each component as a double, then as a float.
constexpr uint64_t kBytesPerDecodedComponent = 12;
// Posing a primitive copies its attributes (morphed; up to ~100 bytes a vertex with
// every attribute and skin weights) and holds a skinned vertex's transform (208 bytes)
// and its posed attributes (~44 bytes): per byte of POSITION decoded (36 a vertex).
constexpr uint64_t kPosingBytesPerDecodedPosition = 10;

uint64_t SaturatingMul(uint64_t a, uint64_t b) { return b && a > UINT64_MAX / b ? UINT64_MAX : a * b; }

uint64_t DecodedBytes(const GltfSource& src, int accessor) {
  if (accessor < 0 || size_t(accessor) >= src.m.accessors.size()) return 0;
  const tinygltf::Accessor& a = src.m.accessors[accessor];
  return SaturatingMul(a.count, uint64_t(ComponentCount(a.type)) * kBytesPerDecodedComponent);
}

}  // namespace

void ChargeGeometry(const GltfSource& src, const std::vector<uint64_t>& instances, bool textured, bool tangents,
                    MemoryBudget& budget) {
  uint64_t largestPosing = 0;
  for (size_t i = 0; i < src.m.meshes.size(); ++i) {
    uint64_t decoded = 0, triangles = 0, colored = 0, posing = 0;
    for (const tinygltf::Primitive& prim : src.m.meshes[i].primitives) {
      decoded += DecodedBytes(src, prim.indices);
      for (const char* attr : {"POSITION", "NORMAL", "COLOR_0", "TEXCOORD_0", "TEXCOORD_1", "TANGENT", "JOINTS_0",
                               "JOINTS_1", "WEIGHTS_0", "WEIGHTS_1"})
        if (auto it = prim.attributes.find(attr); it != prim.attributes.end()) decoded += DecodedBytes(src, it->second);
      for (const auto& target : prim.targets)
        for (const auto& [attr, accessor] : target) decoded += DecodedBytes(src, accessor);
      // A morphed or skinned instance is posed from a copy, one primitive at a time.
      const bool deformed = !prim.targets.empty() || prim.attributes.count("JOINTS_0");
      if (auto it = prim.attributes.find("POSITION"); deformed && it != prim.attributes.end() && instances[i])
        posing = std::max(posing, SaturatingMul(DecodedBytes(src, it->second), kPosingBytesPerDecodedPosition));
      triangles += TriangleCount(src, prim);
      if (prim.attributes.count("COLOR_0")) colored += TriangleCount(src, prim);
    }
    std::string name = "meshes[" + std::to_string(i) + "]";
    budget.Charge(decoded, name + " (decoding its accessors)");
    if (posing > largestPosing) {
      budget.Charge(posing - largestPosing, name + " (posing an instance)");
      largestPosing = posing;
    }
    uint64_t total = SaturatingMul(triangles, instances[i]);
    budget.Charge(SaturatingMul(total, kBytesPerTriangle), name + " (" + std::to_string(triangles) + " triangles × " +
                                                               std::to_string(instances[i]) +
                                                               " instances = " + std::to_string(total) + " triangles)");
    if (colored)
      budget.Charge(SaturatingMul(SaturatingMul(colored, instances[i]), kBytesPerColoredTriangle),
                    name + " (vertex colours of " + std::to_string(colored) + " triangles × " +
                        std::to_string(instances[i]) + " instances)");
    if (textured)
      budget.Charge(SaturatingMul(total, kBytesPerTexturedTriangle),
                    name + " (texture coordinates of " + std::to_string(total) + " triangles)");
    if (tangents)
      budget.Charge(SaturatingMul(total, kBytesPerTangentTriangle),
                    name + " (tangents of " + std::to_string(total) + " triangles)");
  }
}

}  // namespace vkpt::internal

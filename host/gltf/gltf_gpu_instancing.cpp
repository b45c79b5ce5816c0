#include "gltf/gltf_gpu_instancing.h"

#include <cmath>
#include <string>

#include "gltf/gltf_accessors.h"
#include "gltf/node_pose.h"

namespace vkpt::internal {
namespace {

constexpr const char* kExtension = "EXT_mesh_gpu_instancing";
constexpr const char* kAttributes[] = {"TRANSLATION", "ROTATION", "SCALE"};

// The extension's accessor for `attr` (−1: none), its index checked.
int AttributeAccessor(const GltfSource& src, const tinygltf::Value& attributes, const char* attr,
                      const std::string& what) {
  if (!attributes.Has(attr)) return -1;
  const tinygltf::Value& v = attributes.Get(attr);
  if (!v.IsInt() && !v.IsNumber()) src.Fail(what + "." + attr + " is not an accessor index");
  const int index = v.IsInt() ? v.Get<int>() : -1;
  src.CheckIndex(index, src.m.accessors, what + "." + attr);
  return index;
}

// The extension's attributes object of nodes[node]; null without the extension.
const tinygltf::Value* Attributes(const GltfSource& src, int node, std::string& what) {
  const auto ext = src.m.nodes[node].extensions.find(kExtension);
  if (ext == src.m.nodes[node].extensions.end()) return nullptr;
  what = "nodes[" + std::to_string(node) + "].extensions." + kExtension + ".attributes";
  if (!ext->second.IsObject() || !ext->second.Has("attributes") || !ext->second.Get("attributes").IsObject())
    src.Fail(what + " is missing or not an object");
  return &ext->second.Get("attributes");
}

}  // namespace

uint64_t InstanceCount(const GltfSource& src, int node) {
  std::string what;
  const tinygltf::Value* attributes = Attributes(src, node, what);
  if (!attributes) return 1;
  uint64_t count = 0;
  bool any = false;
  for (const char* attr : kAttributes) {
    const int accessor = AttributeAccessor(src, *attributes, attr, what);
    if (accessor < 0) continue;
    const uint64_t n = src.m.accessors[accessor].count;
    if (any && n != count)
      src.Fail(what + "." + attr + " has " + std::to_string(n) + " elements, the other attributes " +
               std::to_string(count));
    count = n;
    any = true;
  }
  if (!any) src.Fail(what + " has none of TRANSLATION, ROTATION and SCALE");
  return count;
}

std::vector<glm::dmat4> InstanceTransforms(const GltfSource& src, int node) {
  std::string what;
  const tinygltf::Value* attributes = Attributes(src, node, what);
  if (!attributes) return {};
  const size_t count = InstanceCount(src, node);
  std::vector<glm::dvec3> t(count, glm::dvec3(0.0)), s(count, glm::dvec3(1.0));
  std::vector<glm::dquat> r(count, glm::dquat(1.0, 0.0, 0.0, 0.0));
  for (const char* attr : kAttributes) {
    const int accessor = AttributeAccessor(src, *attributes, attr, what);
    if (accessor < 0) continue;
    const tinygltf::Accessor& a = src.m.accessors[accessor];
    const bool rotation = std::string(attr) == "ROTATION";
    const bool snorm = a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
                                        a.componentType == TINYGLTF_COMPONENT_TYPE_SHORT);
    if (a.type != (rotation ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3) ||
        !(a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || (rotation && snorm)))
      src.Fail(what + "." + attr + " (accessors[" + std::to_string(accessor) + "]) must be a " +
               (rotation ? "VEC4 of FLOAT or normalized BYTE/SHORT" : "FLOAT VEC3"));
    const std::vector<double> v = ReadAccessor(src, accessor);
    for (double x : v)
      if (!std::isfinite(x)) src.Fail(what + "." + attr + " has a non-finite value");
    for (size_t i = 0; i < count; ++i) {
      if (rotation) {
        const glm::dquat q(v[4 * i + 3], v[4 * i], v[4 * i + 1], v[4 * i + 2]);  // (w, x, y, z)
        if (glm::length(q) < 1e-6)
          src.Fail(what + ".ROTATION element " + std::to_string(i) + " is not a unit quaternion");
        r[i] = q / glm::length(q);
      } else {
        (std::string(attr) == "TRANSLATION" ? t : s)[i] = glm::dvec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
      }
    }
  }
  std::vector<glm::dmat4> m(count);
  for (size_t i = 0; i < count; ++i) {
    NodePose instance;
    instance.translation = t[i];
    instance.rotation = r[i];
    instance.scale = s[i];
    m[i] = instance.Local();
  }
  return m;
}

}  // namespace vkpt::internal

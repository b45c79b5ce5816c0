#include "gltf/gltf_skins.h"

#include <cmath>
#include <set>

#include <glm/gtc/type_ptr.hpp>

#include "gltf/gltf_accessors.h"

namespace vkpt::internal {
namespace {

std::vector<glm::dmat4> ReadInverseBinds(const GltfSource& src, const tinygltf::Skin& skin, const std::string& name) {
  if (skin.inverseBindMatrices < 0) return std::vector<glm::dmat4>(skin.joints.size(), glm::dmat4(1.0));
  src.CheckIndex(skin.inverseBindMatrices, src.m.accessors, name + ".inverseBindMatrices");
  const tinygltf::Accessor& a = src.m.accessors[skin.inverseBindMatrices];
  const std::string what = name + ".inverseBindMatrices (accessors[" + std::to_string(skin.inverseBindMatrices) + "])";
  if (a.type != TINYGLTF_TYPE_MAT4 || a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
    src.Fail(what + " must be a FLOAT MAT4 accessor");
  if (a.count != skin.joints.size())
    src.Fail(what + " has " + std::to_string(a.count) + " matrices for " + std::to_string(skin.joints.size()) +
             " joints");
  const std::vector<double> raw = ReadAccessor(src, skin.inverseBindMatrices);
  std::vector<glm::dmat4> out(a.count);
  for (size_t j = 0; j < out.size(); ++j) {
    for (int c = 0; c < 16; ++c)
      if (!std::isfinite(raw[j * 16 + c])) src.Fail(what + " matrix " + std::to_string(j) + " is not finite");
    out[j] = glm::make_mat4(raw.data() + j * 16);  // column-major
  }
  return out;
}

}  // namespace

std::vector<Skin> ReadSkins(const GltfSource& src) {
  std::vector<Skin> skins;
  for (size_t i = 0; i < src.m.skins.size(); ++i) {
    const tinygltf::Skin& in = src.m.skins[i];
    const std::string name = "skins[" + std::to_string(i) + "]";
    if (in.joints.empty()) src.Fail(name + " has no joints");
    std::set<int> seen;
    for (size_t j = 0; j < in.joints.size(); ++j) {
      src.CheckIndex(in.joints[j], src.m.nodes, name + ".joints[" + std::to_string(j) + "]");
      if (!seen.insert(in.joints[j]).second)
        src.Fail(name + ".joints lists nodes[" + std::to_string(in.joints[j]) + "] twice");
    }
    if (in.skeleton != -1) src.CheckIndex(in.skeleton, src.m.nodes, name + ".skeleton");
    skins.push_back(Skin{in.joints, ReadInverseBinds(src, in, name)});
  }
  return skins;
}

std::vector<glm::dmat4> JointMatrices(const Skin& skin, const std::vector<glm::dmat4>& world) {
  std::vector<glm::dmat4> m(skin.joints.size());
  for (size_t j = 0; j < m.size(); ++j) m[j] = world[skin.joints[j]] * skin.inverseBinds[j];
  return m;
}

}  // namespace vkpt::internal

#include "scene/gltf_materials.h"

#include <algorithm>
#include <cmath>

namespace vkpt {

uint32_t LoadMaterials(const GltfSource& src, Scene& scene) {
  for (size_t i = 0; i < src.m.materials.size(); ++i) {
    const tinygltf::Material& in = src.m.materials[i];
    std::string name = "materials[" + std::to_string(i) + "]";
    const auto& pbr = in.pbrMetallicRoughness;
    Material mat{};
    if (pbr.baseColorFactor.size() != 4) src.Fail(name + ".baseColorFactor must have 4 numbers");
    for (int c = 0; c < 3; ++c) {
      double v = pbr.baseColorFactor[c];
      if (!std::isfinite(v) || v < 0.0 || v > 1.0)
        src.Fail(name + ".baseColorFactor[" + std::to_string(c) + "] is not in [0, 1]");
      mat.baseColor[c] = float(v);
    }
    double strength = 1.0;
    auto it = in.extensions.find("KHR_materials_emissive_strength");
    if (it != in.extensions.end() && it->second.Has("emissiveStrength")) {
      const tinygltf::Value& s = it->second.Get("emissiveStrength");
      if (!s.IsNumber() || !std::isfinite(s.GetNumberAsDouble()) || s.GetNumberAsDouble() < 0.0)
        src.Fail(name + ": KHR_materials_emissive_strength.emissiveStrength is not a number >= 0");
      strength = s.GetNumberAsDouble();
    }
    if (in.emissiveFactor.size() != 3) src.Fail(name + ".emissiveFactor must have 3 numbers");
    for (int c = 0; c < 3; ++c) {
      double v = in.emissiveFactor[c];
      if (!std::isfinite(v) || v < 0.0) src.Fail(name + ".emissiveFactor has a negative or non-finite value");
      mat.emission[c] = float(v * strength);
    }
    if (!std::isfinite(pbr.metallicFactor) || !std::isfinite(pbr.roughnessFactor))
      src.Fail(name + ": metallicFactor/roughnessFactor is not finite");
    mat.metallic = float(std::clamp(pbr.metallicFactor, 0.0, 1.0));
    mat.roughness = float(std::clamp(pbr.roughnessFactor, 0.0, 1.0));
    mat.flags = in.doubleSided ? shader::kMaterialDoubleSided : 0u;
    scene.materials.push_back(mat);
    scene.materialNames.push_back(in.name.empty() ? name : in.name);
  }
  // glTF's default material for primitives without one: white, rough, one-sided.
  const uint32_t defaultMaterial = uint32_t(scene.materials.size());
  Material def{};
  def.baseColor = glm::vec3(1.0f);
  def.metallic = 1.0f;
  def.roughness = 1.0f;
  scene.materials.push_back(def);
  scene.materialNames.push_back("(default)");
  return defaultMaterial;
}

}  // namespace vkpt

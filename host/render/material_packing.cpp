#include "render/material_packing.h"

#include <string>

#include "util/error.h"

namespace vkpt::internal {
namespace {

// A material's textures in the order of the shader's slots (kSlotBaseColor …).
struct SlotTexture {
  uint32_t slot;
  MaterialTexture Material::*texture;
};
const SlotTexture kSlots[] = {
    {shader::kSlotBaseColor, &Material::baseColorTexture},
    {shader::kSlotMetallicRoughness, &Material::metallicRoughnessTexture},
    {shader::kSlotEmissive, &Material::emissiveTexture},
    {shader::kSlotNormal, &Material::normalTexture},
    {shader::kSlotTransmission, &Material::transmissionTexture},
    {shader::kSlotSpecular, &Material::specularTexture},
    {shader::kSlotSpecularColor, &Material::specularColorTexture},
    {shader::kSlotClearcoat, &Material::clearcoatTexture},
    {shader::kSlotClearcoatRoughness, &Material::clearcoatRoughnessTexture},
    {shader::kSlotClearcoatNormal, &Material::clearcoatNormalTexture},
    {shader::kSlotSheenColor, &Material::sheenColorTexture},
    {shader::kSlotSheenRoughness, &Material::sheenRoughnessTexture},
    {shader::kSlotDiffuseTransmission, &Material::diffuseTransmissionTexture},
    {shader::kSlotDiffuseTransmissionColor, &Material::diffuseTransmissionColorTexture},
    {shader::kSlotIridescence, &Material::iridescenceTexture},
    {shader::kSlotIridescenceThickness, &Material::iridescenceThicknessTexture},
    {shader::kSlotAnisotropy, &Material::anisotropyTexture},
};
static_assert(sizeof kSlots / sizeof kSlots[0] == shader::kTextureSlots);

uint32_t AlphaBits(AlphaMode mode) {
  switch (mode) {
    case AlphaMode::kMask: return shader::kMaterialAlphaMask;
    case AlphaMode::kBlend: return shader::kMaterialAlphaBlend;
    default: return 0u;
  }
}

// kMaterialTextured when some slot names a texture, and kMaterialExtensionTextured when
// one of the extensions' slots does: the shaders skip the texture fetches (and the
// extensions' slots) of the materials without.
uint32_t TextureBits(const Material& m) {
  uint32_t bits = 0u;
  for (const SlotTexture& s : kSlots) {
    if (!(m.*s.texture).Present()) continue;
    bits |= shader::kMaterialTextured;
    if (s.slot >= shader::kSlotTransmission) bits |= shader::kMaterialExtensionTextured;
  }
  return bits;
}

}  // namespace

shader::Material PackMaterial(const Material& m) {
  shader::Material g{};  // the padding words stay 0
  g.baseColor = m.baseColor;
  g.metallic = m.metallic;
  g.emission = m.emission;
  g.roughness = m.roughness;
  g.specularColor = m.specularColor;
  g.specular = m.specular;
  g.attenuation = m.attenuation;
  g.ior = m.ior;
  g.transmission = m.transmission;
  g.normalScale = m.normalScale;
  g.alpha = m.alpha;
  g.alphaCutoff = m.alphaCutoff;
  g.clearcoat = m.clearcoat;
  g.clearcoatRoughness = m.clearcoatRoughness;
  g.clearcoatNormalScale = m.clearcoatNormalScale;
  g.sheenColor = m.sheenColor;
  g.sheenRoughness = m.sheenRoughness;
  g.diffuseTransmission = m.diffuseTransmission;
  g.diffuseTransmissionColor = m.diffuseTransmissionColor;
  g.iridescence = m.iridescence;
  g.iridescenceIor = m.iridescenceIor;
  g.iridescenceThicknessMin = m.iridescenceThicknessMin;
  g.iridescenceThickness = m.iridescenceThicknessMax;
  g.anisotropy = m.anisotropyStrength;
  g.dispersion = m.RefractsAsVolume() ? m.dispersion : 0.0f;  // seen nowhere else: no wavelength drawn
  g.anisotropyDirection = glm::vec2(std::cos(m.anisotropyRotation), std::sin(m.anisotropyRotation));
  g.flags = (m.doubleSided ? shader::kMaterialDoubleSided : 0u) | (m.unlit ? shader::kMaterialUnlit : 0u) |
            (m.volume ? shader::kMaterialVolume : 0u) | AlphaBits(m.alphaMode) | TextureBits(m);
  return g;
}

void PackTextureRefs(const Material& m, const std::vector<SceneTexture>& textures,
                     std::vector<shader::TextureRef>& refs) {
  for (const SlotTexture& s : kSlots) {
    const MaterialTexture& t = m.*s.texture;
    const bool colour = shader::SlotIsSrgb(s.slot);
    if (t.Present() && textures.at(t.texture).srgb != colour)
      throw Error("texture " + std::to_string(t.texture) + " holds " + (colour ? "data" : "sRGB colour") +
                  ", but material slot " + std::to_string(s.slot) + " reads " + (colour ? "colour" : "data"));
    refs.push_back({t.Present() ? t.texture : shader::kInvalidIndex, t.texCoord, t.transformU.x, t.transformU.y,
                    t.transformU.z, t.transformV.x, t.transformV.y, t.transformV.z});
  }
}

PackedMaterials PackMaterials(const Scene& scene) {
  PackedMaterials packed;
  packed.materials.reserve(scene.materials.size());
  for (const Material& m : scene.materials) packed.materials.push_back(PackMaterial(m));
  if (!HasMaterialTextures(scene)) return packed;  // the shaders then read no slots at all
  packed.textureRefs.reserve(scene.materials.size() * shader::kTextureSlots);
  for (const Material& m : scene.materials) PackTextureRefs(m, scene.textures, packed.textureRefs);
  return packed;
}

}  // namespace vkpt::internal

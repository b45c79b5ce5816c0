#include "render/material_packing.h"

#include <string>

#include "util/error.h"

namespace vkpt::internal {
namespace {

// The scene's slots are the shaders' (both generated from gpu_records.def), in one order.
static_assert(kTextureSlotCount == shader::kTextureSlots);
static_assert(uint32_t(TextureSlot::kTransmission) == shader::kSlotTransmission);

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
  for (uint32_t slot = 0; slot < kTextureSlotCount; ++slot) {
    if (!m.textures[slot].Present()) continue;
    bits |= shader::kMaterialTextured;
    if (slot >= shader::kSlotTransmission) bits |= shader::kMaterialExtensionTextured;
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
  for (uint32_t slot = 0; slot < kTextureSlotCount; ++slot) {
    const MaterialTexture& t = m.textures[slot];
    const bool colour = kTextureSlotInfo[slot].srgb;
    if (t.Present() && textures.at(t.texture).srgb != colour)
      throw Error("texture " + std::to_string(t.texture) + " holds " + (colour ? "data" : "sRGB colour") +
                  ", but material slot " + std::to_string(slot) + " (" + kTextureSlotInfo[slot].name + ") reads " +
                  (colour ? "colour" : "data"));
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

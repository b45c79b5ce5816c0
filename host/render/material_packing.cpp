#include "render/material_packing.h"

namespace vkpt {
namespace {

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
uint32_t TextureBits(const shader::TextureRef* textures) {
  uint32_t bits = 0u;
  for (uint32_t slot = 0; textures && slot < shader::kTextureSlots; ++slot) {
    if (textures[slot].texture == shader::kInvalidIndex) continue;
    bits |= shader::kMaterialTextured;
    if (slot >= shader::kSlotTransmission) bits |= shader::kMaterialExtensionTextured;
  }
  return bits;
}

}  // namespace

shader::Material PackMaterial(const Material& m, const shader::TextureRef* textures) {
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
  g.flags = (m.doubleSided ? shader::kMaterialDoubleSided : 0u) | (m.unlit ? shader::kMaterialUnlit : 0u) |
            (m.volume ? shader::kMaterialVolume : 0u) | AlphaBits(m.alphaMode) | TextureBits(textures);
  return g;
}

std::vector<shader::Material> PackMaterials(const Scene& scene) {
  std::vector<shader::Material> packed;
  packed.reserve(scene.materials.size());
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    const shader::TextureRef* textures =
        scene.textureRefs.empty() ? nullptr : &scene.textureRefs.at(i * shader::kTextureSlots);
    packed.push_back(PackMaterial(scene.materials[i], textures));
  }
  return packed;
}

}  // namespace vkpt

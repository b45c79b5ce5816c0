// A glTF material (spec §3.9 and the KHR_materials_* extensions vkpt renders) as the
// physics reads it: factors in the units shared/bsdf.h uses, with the glTF switches as
// plain values. How the GPU stores it (std430 padding, flag bits) is render/'s business
// (render/material_packing.h); nothing here knows it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "scene/texture_slots.h"

namespace vkpt::internal {

// glTF §3.9.4 alphaMode: how the base colour's alpha covers the surface (shared/alpha.h).
enum class AlphaMode {
  kOpaque,  // alpha is ignored
  kMask,    // the surface is present where alpha >= alphaCutoff
  kBlend,   // the surface is present with probability alpha
};
// glTF's names of the modes, in the enum's order.
inline constexpr const char* kAlphaModeNames[] = {"OPAQUE", "MASK", "BLEND"};

// KHR_materials_ior: 0 (Fresnel is 1 at every angle) or an index of refraction in [1, 1e6].
inline bool IorHolds(double ior) { return ior == 0.0 || (ior >= 1.0 && ior <= 1e6); }

// A material's use of a texture (glTF textureInfo): which of Scene::textures, which
// TEXCOORD set, and KHR_texture_transform as a 2×3 matrix, the texture read at
// (dot(transformU, (u, v, 1)), dot(transformV, (u, v, 1))). Default: no texture.
struct MaterialTexture {
  static constexpr uint32_t kNone = 0xFFFFFFFFu;
  uint32_t texture = kNone;  // into Scene::textures
  uint32_t texCoord = 0;     // 0 or 1: vkpt reads TEXCOORD_0 and TEXCOORD_1
  glm::vec3 transformU{1.0f, 0.0f, 0.0f};
  glm::vec3 transformV{0.0f, 1.0f, 0.0f};
  bool Present() const { return texture != kNone; }
};

// Value-initialised (Material{}), every number is 0: a black, non-emitting diffuse
// surface without a specular layer, opaque and one-sided. The loader sets every field
// (glTF's defaults where the file says nothing); tests set the few they need.
struct Material {
  glm::vec3 baseColor{0.0f};  // baseColorFactor's RGB
  float alpha = 0.0f;         // baseColorFactor's alpha
  float metallic = 0.0f;
  float roughness = 0.0f;
  glm::vec3 emission{0.0f};       // emitted radiance Le = emissiveFactor × emissiveStrength
  float specular = 0.0f;          // KHR_materials_specular: scales F0 and F90 (0: no specular layer)
  glm::vec3 specularColor{0.0f};  // KHR_materials_specular: tints the dielectric F0
  float ior = 0.0f;               // KHR_materials_ior (1.5 when absent; 0: Fresnel is 1)
  float transmission = 0.0f;      // KHR_materials_transmission: the transmissive share of the dielectric base
  // KHR_materials_volume: thickness > 0 makes the surface bound a volume (rays refract,
  // and attenuate inside by σ = −ln(attenuationColor) / attenuationDistance per unit
  // length); false: a thin wall. `attenuation` is σ whether or not `volume` is set.
  bool volume = false;
  glm::vec3 attenuation{0.0f};
  float normalScale = 0.0f;  // normalTexture.scale: scales the tangent-space normal's x and y
  AlphaMode alphaMode = AlphaMode::kOpaque;
  float alphaCutoff = 0.0f;  // kMask: the cut between absent and present
  bool doubleSided = false;
  bool unlit = false;  // KHR_materials_unlit: shows baseColor, reflects nothing
  // KHR_materials_clearcoat: a clear GGX layer over the rest (shared/clearcoat.h).
  float clearcoat = 0.0f;  // 0: no coat
  float clearcoatRoughness = 0.0f;
  float clearcoatNormalScale = 0.0f;  // clearcoatNormalTexture.scale
  // KHR_materials_sheen: a fibre lobe over the base, under the coat (shared/sheen.h).
  glm::vec3 sheenColor{0.0f};  // black: no sheen
  float sheenRoughness = 0.0f;
  // KHR_materials_diffuse_transmission: the diffuse base passed through (shared/bsdf.h).
  float diffuseTransmission = 0.0f;  // 0: none
  glm::vec3 diffuseTransmissionColor{1.0f};
  // KHR_materials_iridescence: a thin film on the material (shared/iridescence.h).
  float iridescence = 0.0f;  // 0: no film
  float iridescenceIor = 1.3f;
  float iridescenceThicknessMin = 100.0f;  // nm
  float iridescenceThicknessMax = 400.0f;  // nm
  // KHR_materials_anisotropy: the GGX lobe stretched along a direction (shared/microfacet.h).
  float anisotropyStrength = 0.0f;  // 0: isotropic
  float anisotropyRotation = 0.0f;  // radians, counter-clockwise from the tangent
  // KHR_materials_dispersion: the volume's index varies with wavelength (shared/dispersion.h).
  float dispersion = 0.0f;  // 20 / the Abbe number Vd; 0: none

  // The textures that scale the factors above, one per slot of the generated
  // scene/texture_slots.h (declared in shaders/shared/gpu_records.def, which says what
  // each slot scales; shared/material_textures.h applies them).
  std::array<MaterialTexture, kTextureSlotCount> textures;
  MaterialTexture& texture(TextureSlot s) { return textures[size_t(s)]; }
  const MaterialTexture& texture(TextureSlot s) const { return textures[size_t(s)]; }

  // Whether the material refracts as the boundary of a volume, where alone its dispersion
  // is seen.
  bool RefractsAsVolume() const { return volume && transmission > 0.0f && ior > 1.0f && !unlit; }

  // Whether some texture above is present.
  bool Textured() const {
    for (const MaterialTexture& t : textures)
      if (t.Present()) return true;
    return false;
  }
};

}  // namespace vkpt::internal

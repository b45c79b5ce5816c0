// The GPU layout of a material (shared/bsdf_prepare.h reads it), shared by C++ and GLSL
// under layout.h's rules (std430, 4-byte scalars and (vec3, scalar) pairs;
// host/render/gpu_layout.cpp static_asserts the offsets).
#ifndef VKPT_MATERIAL_LAYOUT_H
#define VKPT_MATERIAL_LAYOUT_H
#include "prelude.h"  // first, as in every shared header

VKPT_BEGIN_NAMESPACE

const uint kMaterialDoubleSided = 1u;
const uint kMaterialUnlit = 2u;     // KHR_materials_unlit: shows baseColor, reflects nothing
const uint kMaterialVolume = 4u;    // KHR_materials_volume with thickness > 0: refracts, attenuates inside
const uint kMaterialTextured = 8u;  // some TextureRef of the material names a texture
// glTF alphaMode (shared/alpha.h): MASK cuts the surface where its alpha is below
// alphaCutoff, BLEND makes it present with probability alpha; neither: OPAQUE.
const uint kMaterialAlphaMask = 16u;
const uint kMaterialAlphaBlend = 32u;
const uint kMaterialAlphaTested = kMaterialAlphaMask | kMaterialAlphaBlend;
const uint kMaterialExtensionTextured = 64u;  // a TextureRef of slot kSlotTransmission or above names a texture

// A glTF metallic-roughness material (shared/bsdf.h) plus emission.
struct Material {
  vec3 baseColor;
  float metallic;
  vec3 emission;  // emitted radiance Le = emissiveFactor * emissiveStrength
  float roughness;
  vec3 specularColor;  // KHR_materials_specular: tints the dielectric F0
  float specular;      // KHR_materials_specular: scales F0 and F90 (0: no specular layer)
  vec3 attenuation;    // KHR_materials_volume: σ = −ln(attenuationColor) / attenuationDistance, per unit length
  float ior;           // KHR_materials_ior (1.5 when absent; 0: Fresnel is 1)
  float transmission;  // KHR_materials_transmission: the share of the dielectric base that is transmissive
  uint flags;          // kMaterial* above
  float normalScale;   // normalTexture.scale: scales the tangent-space normal's x and y
  float alpha;         // baseColorFactor's alpha
  float alphaCutoff;   // MASK: the surface is present where its alpha is >= alphaCutoff
  float clearcoat;     // KHR_materials_clearcoat: the coat's factor (0: no coat)
  float clearcoatRoughness;
  float clearcoatNormalScale;  // clearcoatNormalTexture.scale
  vec3 sheenColor;             // KHR_materials_sheen: the sheen's colour (0: no sheen)
  float sheenRoughness;
  vec3 diffuseTransmissionColor;  // KHR_materials_diffuse_transmission
  float diffuseTransmission;      // the share of the diffuse base transmitted (0: none)
  float iridescence;              // KHR_materials_iridescence: the film's weight (0: no film)
  float iridescenceIor;           // the film's index
  float iridescenceThicknessMin;  // nm, where the thickness texture's G is 0
  float iridescenceThickness;     // nm: the maximum (G = 1), the film's thickness once textured
  float anisotropy;               // KHR_materials_anisotropy: the strength (0: isotropic)
  float dispersion;               // KHR_materials_dispersion: 20/Vd where the material refracts (0: none)
  vec2 anisotropyDirection;       // in tangent space: (cos, sin) of the rotation, turned by the texture
};

VKPT_END_NAMESPACE

#endif

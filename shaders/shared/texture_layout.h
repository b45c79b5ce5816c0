// The GPU layout of textures (shared/texture.h) and of a material's texture slots
// (shared/material_textures.h), shared by C++ and GLSL under layout.h's rules (std430,
// 4-byte scalars; host/render/gpu_layout.cpp static_asserts the sizes).
#ifndef VKPT_TEXTURE_LAYOUT_H
#define VKPT_TEXTURE_LAYOUT_H
#include "prelude.h"  // first, as in every shared header

VKPT_BEGIN_NAMESPACE

// A texture: an image with its mip levels in the texel store, and how it is sampled.
// Level l is max(1, width >> l) × max(1, height >> l) texels, row-major from the image's
// top row. The store holds at `offset` one word per level, the offset of that level,
// then the levels.
struct Texture {
  uint offset;  // in words (RGBA8 texels) of the store
  uint width;
  uint height;
  uint mode;  // kTextureWrapS* | kTextureWrapT* | filters | levels << kTextureLevelShift
};
// Wrap modes (glTF sampler wrapS/wrapT), 2 bits each.
const uint kWrapRepeat = 0u;
const uint kWrapClampToEdge = 1u;
const uint kWrapMirroredRepeat = 2u;
const uint kTextureWrapSShift = 0u;
const uint kTextureWrapTShift = 2u;
const uint kTextureMagLinear = 16u;   // magFilter LINEAR (else NEAREST)
const uint kTextureMinLinear = 32u;   // minFilter *LINEAR* within a level (else NEAREST)
const uint kTextureMipNearest = 64u;  // minFilter *_MIPMAP_NEAREST: the nearest level
const uint kTextureMipLinear = 128u;  // minFilter *_MIPMAP_LINEAR: between two levels (neither: level 0)
const uint kTextureLevelShift = 16u;  // the number of levels, 1 + floor(log2(max(width, height)))
// The byte → float tables, each exactly rounded: [0, 256) sRGB colour to linear, [256,
// 512) b / 255. The GPU reads the first only and computes b / 255 (texture.h's UnormByte,
// the same bits); the CPU reads both, a table being faster there than the arithmetic.
const uint kTexelDecodeSize = 512u;
const uint kTexelDecodeLinear = 256u;

// A material's use of a texture (glTF textureInfo): which texture, which TEXCOORD set,
// and the KHR_texture_transform as a 2×3 matrix, uv' = (m00 u + m01 v + m02, m10 u + m11 v + m12).
struct TextureRef {
  uint texture;   // index into the Texture table, or kInvalidIndex: the slot is unused
  uint texCoord;  // 0 or 1
  float m00;
  float m01;
  float m02;
  float m10;
  float m11;
  float m12;
};
// The texture slots of a material, kTextureSlots TextureRefs each (kBindingMaterialTextures).
const uint kSlotBaseColor = 0u;                  // RGB × baseColor, A × alpha
const uint kSlotMetallicRoughness = 1u;          // G × roughness, B × metallic
const uint kSlotEmissive = 2u;                   // RGB × emission
const uint kSlotNormal = 3u;                     // tangent-space normal (shared/normal_map.h)
const uint kSlotTransmission = 4u;               // R × transmission (KHR_materials_transmission)
const uint kSlotSpecular = 5u;                   // A × specular (KHR_materials_specular)
const uint kSlotSpecularColor = 6u;              // RGB × specularColor (KHR_materials_specular)
const uint kSlotClearcoat = 7u;                  // R × clearcoat (KHR_materials_clearcoat)
const uint kSlotClearcoatRoughness = 8u;         // G × clearcoatRoughness
const uint kSlotClearcoatNormal = 9u;            // the coat's tangent-space normal
const uint kSlotSheenColor = 10u;                // RGB × sheenColor (KHR_materials_sheen)
const uint kSlotSheenRoughness = 11u;            // A × sheenRoughness
const uint kSlotDiffuseTransmission = 12u;       // A × diffuseTransmission (KHR_materials_diffuse_transmission)
const uint kSlotDiffuseTransmissionColor = 13u;  // RGB × diffuseTransmissionColor
const uint kSlotIridescence = 14u;               // R × iridescence (KHR_materials_iridescence)
const uint kSlotIridescenceThickness = 15u;      // G: the film's thickness between its minimum and maximum
const uint kSlotAnisotropy = 16u;                // RG direction, B × anisotropy (KHR_materials_anisotropy)
// The slots whose RGB is colour, sRGB-encoded (glTF 2.0 §3.9.2 and the extensions' colour
// textures); every other slot's bytes, and every alpha, are linear. A texture used both
// ways is two textures (gltf/gltf_textures.cpp).
const uint kSrgbSlots = (1u << kSlotBaseColor) | (1u << kSlotEmissive) | (1u << kSlotSpecularColor) |
                        (1u << kSlotSheenColor) | (1u << kSlotDiffuseTransmissionColor);
// Whether slot `slot` holds colour: a constant wherever a slot is named, so that lavapipe
// compiles only the decode the slot needs (texture.h).
VKPT_FN bool SlotIsSrgb(uint slot) { return ((kSrgbSlots >> slot) & 1u) != 0u; }
const uint kTextureSlots = 17u;

VKPT_END_NAMESPACE

#endif

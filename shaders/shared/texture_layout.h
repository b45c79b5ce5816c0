// The sampling modes and decode tables of textures (shared/texture.h), shared by C++ and
// GLSL; the records Texture and TextureRef, and the material's texture slots
// (shared/material_textures.h), are in gpu_records.def.
#ifndef VKPT_TEXTURE_LAYOUT_H
#define VKPT_TEXTURE_LAYOUT_H
#include "prelude.h"             // first, as in every shared header
#include "shared/gpu_records.h"  // kSrgbSlots

VKPT_BEGIN_NAMESPACE

// Texture::mode. Wrap modes (glTF sampler wrapS/wrapT), 2 bits each.
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

// Whether slot `slot` holds colour: a constant wherever a slot is named, so that lavapipe
// compiles only the decode the slot needs (texture.h).
VKPT_FN bool SlotIsSrgb(uint slot) { return ((kSrgbSlots >> slot) & 1u) != 0u; }

VKPT_END_NAMESPACE

#endif

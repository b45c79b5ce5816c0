// The flag bits of a material (Material::flags; the record is in gpu_records.def, and
// shared/bsdf_prepare.h reads it), shared by C++ and GLSL.
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

VKPT_END_NAMESPACE

#endif

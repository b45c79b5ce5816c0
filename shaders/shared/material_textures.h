// A material's textures applied at a surface point (glTF 2.0 §3.9): the base colour
// texture multiplies baseColorFactor, the metallic-roughness texture's G and B channels
// the roughness and metallic factors, the emissive texture the emissive factor; and the
// material extensions' textures their factors: KHR_materials_transmission's R channel
// the transmission, KHR_materials_specular's A channel the specular factor and its colour
// texture the specular colour, KHR_materials_clearcoat's R and G channels the coat's
// factor and roughness (its normal texture is shading_frame.h's), KHR_materials_sheen's
// colour texture the sheen's colour and its roughness texture's A channel its roughness,
// KHR_materials_diffuse_transmission's A channel its factor and its colour texture its
// colour, KHR_materials_iridescence's R channel its factor and its thickness texture's G
// channel the film's thickness between its minimum and maximum, KHR_materials_anisotropy's
// B channel its strength and RG its direction in tangent space (2·RG − 1, turned by the
// rotation; without the texture the rotation alone).
//
// Scene access, as in texture.h, plus
//   VKPT_TEXTURE_REF(i)  TextureRef i: slot s of material m is i = m · kTextureSlots + s
//   VKPT_UVS_OF(i)       the TriangleUVs of scene triangle i
#ifndef VKPT_MATERIAL_TEXTURES_H
#define VKPT_MATERIAL_TEXTURES_H
#include "prelude.h"  // first, as in every shared header

#include "layout.h"
#include "ray_cone.h"
#include "texture.h"

// A shader may define VKPT_TEXTURES as a specialization constant that is false when no
// material has a texture (and the scene has no TriangleUVs to read).
#ifndef VKPT_TEXTURES
#define VKPT_TEXTURES true
#endif
// Likewise VKPT_EXTENSION_TEXTURES, false when no material has a texture in a slot from
// kSlotTransmission on (kMaterialExtensionTextured).
#ifndef VKPT_EXTENSION_TEXTURES
#define VKPT_EXTENSION_TEXTURES true
#endif
// And clearcoat.h's VKPT_CLEARCOAT, sheen.h's VKPT_SHEEN, bsdf.h's
// VKPT_DIFFUSE_TRANSMISSION, iridescence.h's VKPT_IRIDESCENCE and microfacet.h's
// VKPT_ANISOTROPY (not included here: path.h's seams must come first).
#ifndef VKPT_CLEARCOAT
#define VKPT_CLEARCOAT true
#endif
#ifndef VKPT_SHEEN
#define VKPT_SHEEN true
#endif
#ifndef VKPT_DIFFUSE_TRANSMISSION
#define VKPT_DIFFUSE_TRANSMISSION true
#endif
#ifndef VKPT_IRIDESCENCE
#define VKPT_IRIDESCENCE true
#endif
#ifndef VKPT_ANISOTROPY
#define VKPT_ANISOTROPY true
#endif

VKPT_BEGIN_NAMESPACE

// TEXCOORD_<set> at barycentrics (b1, b2).
VKPT_FN vec2 InterpolatedUV(TriangleUVs t, uint set, float b1, float b2) {
  vec2 a = set == 0u ? t.uv00 : t.uv10;
  vec2 b = set == 0u ? t.uv01 : t.uv11;
  vec2 c = set == 0u ? t.uv02 : t.uv12;
  VKPT_PRECISE vec2 uv = (1.0f - b1 - b2) * a + b1 * b + b2 * c;
  return uv;
}

// Slot `slot` of `material` at the point, or 1 where the slot has no texture, at the mip
// level of a ray cone's `footprint` (ray_cone.h; kLevelZero: level 0).
VKPT_FN vec4 SampleSlot(VKPT_SCENE_PARAM uint material, uint slot, TriangleUVs uvs, float b1, float b2,
                        float footprint) {
  TextureRef ref = VKPT_TEXTURE_REF(material * kTextureSlots + slot);
  if (ref.texture == kInvalidIndex) return vec4(1.0f);
  Texture tex = VKPT_TEXTURE(ref.texture);
  vec2 uv = TransformUV(ref, InterpolatedUV(uvs, ref.texCoord, b1, b2));
  float lod = footprint <= kLevelZero ? 0.0f : TextureLod(footprint, ref, tex, uvs);
  return SampleTexture(VKPT_SCENE_ARG tex, uv, lod, SlotIsSrgb(slot));
}

// `mat` (material `material`, read from the table) at the point (b1, b2) of a triangle
// with texture coordinates `uvs`. Colour textures (base colour, specular colour) are read
// at the mip level of ray cone footprint `footprints.x`, the data textures
// (metallic-roughness, the extensions' factors) and normal maps (shading_frame.h) at
// that of `footprints.y` — level 0, as the estimator reads them (path.h's TextureCones):
// light is linear in a colour, so a filtered colour gives the average of the footprint's
// light, but not in a roughness, a metalness or a normal, whose filtered value gives
// other light (docs/design-notes.md, "Texture level of detail"). Emission reads level 0,
// as light sampling does (EmissiveTexture), so both MIS strategies see the same emitter.
VKPT_FN void ApplyMaterialTextures(VKPT_SCENE_PARAM VKPT_INOUT(Material) mat, uint material, TriangleUVs uvs, float b1,
                                   float b2, vec2 footprints) {
  float footprint = footprints.x, data = footprints.y;
  mat.baseColor *= vec3(SampleSlot(VKPT_SCENE_ARG material, kSlotBaseColor, uvs, b1, b2, footprint));
  vec4 mr = SampleSlot(VKPT_SCENE_ARG material, kSlotMetallicRoughness, uvs, b1, b2, data);
  mat.roughness *= mr.g;
  mat.metallic *= mr.b;
  mat.emission *= vec3(SampleSlot(VKPT_SCENE_ARG material, kSlotEmissive, uvs, b1, b2, kLevelZero));
  if (VKPT_EXTENSION_TEXTURES && (mat.flags & kMaterialExtensionTextured) != 0u) {
    mat.transmission *= SampleSlot(VKPT_SCENE_ARG material, kSlotTransmission, uvs, b1, b2, data).r;
    mat.specular *= SampleSlot(VKPT_SCENE_ARG material, kSlotSpecular, uvs, b1, b2, data).a;
    mat.specularColor *= vec3(SampleSlot(VKPT_SCENE_ARG material, kSlotSpecularColor, uvs, b1, b2, footprint));
    if (VKPT_CLEARCOAT && mat.clearcoat > 0.0f) {
      mat.clearcoat *= SampleSlot(VKPT_SCENE_ARG material, kSlotClearcoat, uvs, b1, b2, data).r;
      mat.clearcoatRoughness *= SampleSlot(VKPT_SCENE_ARG material, kSlotClearcoatRoughness, uvs, b1, b2, data).g;
    }
    if (VKPT_SHEEN && MaxComponent(mat.sheenColor) > 0.0f) {
      mat.sheenColor *= vec3(SampleSlot(VKPT_SCENE_ARG material, kSlotSheenColor, uvs, b1, b2, footprint));
      mat.sheenRoughness *= SampleSlot(VKPT_SCENE_ARG material, kSlotSheenRoughness, uvs, b1, b2, data).a;
    }
    if (VKPT_DIFFUSE_TRANSMISSION && mat.diffuseTransmission > 0.0f) {
      mat.diffuseTransmission *= SampleSlot(VKPT_SCENE_ARG material, kSlotDiffuseTransmission, uvs, b1, b2, data).a;
      mat.diffuseTransmissionColor *=
          vec3(SampleSlot(VKPT_SCENE_ARG material, kSlotDiffuseTransmissionColor, uvs, b1, b2, footprint));
    }
    if (VKPT_IRIDESCENCE && mat.iridescence > 0.0f) {
      mat.iridescence *= SampleSlot(VKPT_SCENE_ARG material, kSlotIridescence, uvs, b1, b2, data).r;
      float g = SampleSlot(VKPT_SCENE_ARG material, kSlotIridescenceThickness, uvs, b1, b2, data).g;
      mat.iridescenceThickness = mix(mat.iridescenceThicknessMin, mat.iridescenceThickness, g);
    }
    if (VKPT_ANISOTROPY && mat.anisotropy > 0.0f &&
        VKPT_TEXTURE_REF(material * kTextureSlots + kSlotAnisotropy).texture != kInvalidIndex) {
      vec4 t = SampleSlot(VKPT_SCENE_ARG material, kSlotAnisotropy, uvs, b1, b2, data);
      mat.anisotropy *= t.b;
      vec2 d = 2.0f * vec2(t) - vec2(1.0f);
      float length2 = dot(d, d);
      d = length2 > 0.0f ? d * inversesqrt(length2) : vec2(1.0f, 0.0f);
      vec2 r = mat.anisotropyDirection;  // the rotation's (cos, sin)
      mat.anisotropyDirection = vec2(r.x * d.x - r.y * d.y, r.y * d.x + r.x * d.y);
    }
  }
}

// The emissive texture alone, for light sampling: the factor by which the emission at
// (b1, b2) of scene triangle `sourceIndex` differs from its material's emissive factor.
VKPT_FN vec3 EmissiveTexture(VKPT_SCENE_PARAM uint material, uint sourceIndex, float b1, float b2) {
  return vec3(SampleSlot(VKPT_SCENE_ARG material, kSlotEmissive, VKPT_UVS_OF(sourceIndex), b1, b2, kLevelZero));
}

// The clear coat factor over an emitter (factor `coat`, material flags `flags`) at (b1, b2)
// of scene triangle `sourceIndex`, read at level 0 as the emission is, so that both MIS
// strategies dim the same emission (fresnel.h's CoatTransmittance).
VKPT_FN float EmitterCoat(VKPT_SCENE_PARAM float coat, uint flags, uint material, uint sourceIndex, float b1,
                          float b2) {
  if (VKPT_TEXTURES && VKPT_EXTENSION_TEXTURES && coat > 0.0f && (flags & kMaterialExtensionTextured) != 0u)
    coat *= SampleSlot(VKPT_SCENE_ARG material, kSlotClearcoat, VKPT_UVS_OF(sourceIndex), b1, b2, kLevelZero).r;
  return coat;
}

VKPT_END_NAMESPACE

#endif

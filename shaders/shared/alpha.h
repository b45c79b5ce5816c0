// glTF alpha coverage (spec §3.9.4) in both traversals: a hit on a MASK or BLEND surface
// that its alpha leaves out is passed through, by closest-hit and shadow rays alike.
//
// alpha = baseColorFactor.a × baseColorTexture.a × COLOR_0.a. MASK keeps the surface
// where alpha ≥ alphaCutoff. BLEND is rendered as stochastic opacity (Enderton et al.
// 2010, "Stochastic Transparency"; pbrt-v4's alpha test does the same): each ray finds
// the surface with probability alpha, so on average it lets 1 − alpha of the light
// through, and the surface then shades as if opaque. The uniform number deciding that is
// a hash of the ray's key (RayAlphaKey in path.h, from the sample's random streams) and
// the scene triangle: not drawn in traversal order, so the CPU's and the GPU's walks,
// which meet triangles in different orders, decide alike, and a triangle that spatial
// splits put in several leaves gets one decision per ray.
//
// Scene access as in material_textures.h, plus VKPT_MATERIAL(i) and
// VKPT_VERTEX_COLORS_OF(i) (the TriangleColors of scene triangle i).
#ifndef VKPT_ALPHA_H
#define VKPT_ALPHA_H
#include "prelude.h"  // first, as in every shared header

#include "layout.h"
#include "material_textures.h"
#include "rng.h"
#include "vertex_color.h"

// A shader may define VKPT_ALPHA as a specialization constant that is false when no
// triangle's material is MASK or BLEND, so that traversal compiles no alpha test.
#ifndef VKPT_ALPHA
#define VKPT_ALPHA true
#endif
// As in shading_frame.h: false when no triangle has COLOR_0.
#ifndef VKPT_VERTEX_COLORS
#define VKPT_VERTEX_COLORS true
#endif

VKPT_BEGIN_NAMESPACE

// The share of the surface present at (b1, b2) of scene triangle `sourceIndex`, whose
// material `material` is `mat`: 1 for OPAQUE, 0 or 1 for MASK, alpha for BLEND.
VKPT_FN float Coverage(VKPT_SCENE_PARAM Material mat, uint material, uint sourceIndex, float b1, float b2) {
  if ((mat.flags & kMaterialAlphaTested) == 0u) return 1.0f;
  float alpha = mat.alpha;
  if (VKPT_TEXTURES && (mat.flags & kMaterialTextured) != 0u)
    alpha *= SampleSlot(VKPT_SCENE_ARG material, kSlotBaseColor, VKPT_UVS_OF(sourceIndex), b1, b2, kLevelZero).a;
  if (VKPT_VERTEX_COLORS) alpha *= InterpolatedColor(VKPT_VERTEX_COLORS_OF(sourceIndex), b1, b2).a;
  if ((mat.flags & kMaterialAlphaMask) != 0u) return alpha >= mat.alphaCutoff ? 1.0f : 0.0f;
  return alpha;
}

// The uniform number in [0, 1) that decides whether the ray with key `key` finds scene
// triangle `sourceIndex` where its coverage is fractional.
VKPT_FN float AlphaDecision(uint key, uint sourceIndex) {
  return ToUnitFloat(Pcg4d(uvec4(key, sourceIndex, 0xA1FAu, 0u)).x);
}

// Whether the ray with key `key` passes through the hit (b1, b2) of a triangle of
// material `material`, scene triangle `sourceIndex`.
VKPT_FN bool AlphaRejects(VKPT_SCENE_PARAM uint material, uint sourceIndex, float b1, float b2, uint key) {
  Material mat = VKPT_MATERIAL(material);
  if ((mat.flags & kMaterialAlphaTested) == 0u) return false;
  float coverage = Coverage(VKPT_SCENE_ARG mat, material, sourceIndex, b1, b2);
  return (mat.flags & kMaterialAlphaMask) != 0u ? coverage == 0.0f : AlphaDecision(key, sourceIndex) >= coverage;
}

VKPT_END_NAMESPACE

#endif

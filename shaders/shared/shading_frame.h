// What the estimator knows about a surface point a ray has hit: position, geometric
// normal, the shading frame the BSDF works in (and the clear coat's normal), the
// material and whether it emits.
// Scene access as in path.h, plus VKPT_SHADING(i), VKPT_VERTEX_COLORS_OF(i) and
// VKPT_TANGENTS_OF(i): the TriangleShading, TriangleColors and TriangleTangents of scene
// triangle i, and material_textures.h's.
#ifndef VKPT_SHADING_FRAME_H
#define VKPT_SHADING_FRAME_H
#include "estimator.h"
#include "fresnel.h"
#include "layout.h"
#include "material_textures.h"
#include "normal_map.h"
#include "prelude.h"
#include "sampling.h"
#include "shading_normal.h"
#include "vertex_color.h"

// A shader may define VKPT_SMOOTH_NORMALS as a specialization constant that is false
// when no triangle has vertex normals (host/render/render_scene.cpp leaves flat-shaded
// ones without): lavapipe runs an if's body even when no lane takes it, so only a
// constant spares every hit the three octahedral decodes.
#ifndef VKPT_SMOOTH_NORMALS
#define VKPT_SMOOTH_NORMALS true
#endif
// Likewise VKPT_VERTEX_COLORS: false when no triangle has COLOR_0 (and the scene has no
// TriangleColors to read).
#ifndef VKPT_VERTEX_COLORS
#define VKPT_VERTEX_COLORS true
#endif
// And VKPT_NORMAL_MAPS: false when no material has a normal texture (and the scene has no
// TriangleTangents to read).
#ifndef VKPT_NORMAL_MAPS
#define VKPT_NORMAL_MAPS true
#endif
// And microfacet.h's VKPT_ANISOTROPY (not included here: path.h's seams must come first).
#ifndef VKPT_ANISOTROPY
#define VKPT_ANISOTROPY true
#endif

VKPT_BEGIN_NAMESPACE

struct SurfaceHit {
  vec3 p;
  uint light;       // the hit triangle's light-table entry, or kInvalidIndex
  vec3 ng;          // unit geometric normal, on the side the ray arrived from
  bool emits;       // the material emits towards the ray (front face, or double-sided)
  bool frontFace;   // the ray arrived on the side the triangle's winding faces
  Frame frame;      // shading frame; frame.n is the shading normal
  vec3 coatNormal;  // KHR_materials_clearcoat's normal: its own normal map, else the vertex normal
  Material material;
  float curvature;  // of the vertex normals (ray_cone.h), in textured scenes; else 0
};

// The shading normal ns (interpolated vertex normals, on the side of ng) adapted so that
// the mirror direction of ωo lies above the geometric surface (Keller et al. 2017, "The
// Iray Light Transport Simulation and Rendering System", arXiv:1705.01263): where it would not, ns
// is bent towards ng until the reflection r of ωo sits at cos = kMinReflectionCos above
// the surface, ns' = normalize(ωo + r'). Without it, glossy surfaces whose normals bend
// away from the viewer (coarse spheres near their silhouettes) sample mostly directions
// below the surface and turn black; those directions are still refused (path.h), so no
// light leaks through the geometry.
const float kMinReflectionCos = 0.01f;

VKPT_FN vec3 AdaptShadingNormal(vec3 ns, vec3 ng, vec3 wo) {
  vec3 r = 2.0f * dot(wo, ns) * ns - wo;
  float h = dot(r, ng);
  if (h >= kMinReflectionCos) return ns;
  vec3 lifted = normalize(r + (kMinReflectionCos - h) * ng);
  return normalize(wo + lifted);
}

// The tangent-space normal in slot `slot` (kSlotNormal, kSlotClearcoatNormal) of
// `material` at the point, with w = 1; w = 0 where the slot has no texture.
VKPT_FN vec4 NormalMapTexel(VKPT_SCENE_PARAM uint material, uint slot, TriangleUVs uvs, float b1, float b2,
                            float footprint) {
  if (VKPT_TEXTURE_REF(material * kTextureSlots + slot).texture == kInvalidIndex) return vec4(0.0f);
  return vec4(vec3(SampleSlot(VKPT_SCENE_ARG material, slot, uvs, b1, b2, footprint)), 1.0f);
}

// The interpolated vertex normal of `tri` at the hit, with w = 1; (ng, 0) where it has
// none, or they cancel out (or give NaN). Sets `curvature` (ray_cone.h) in textured scenes.
VKPT_FN vec4 VertexNormal(VKPT_SCENE_PARAM Triangle tri, HitRecord hit, vec3 ng, VKPT_INOUT(float) curvature) {
  if (!VKPT_SMOOTH_NORMALS) return vec4(ng, 0.0f);
  TriangleShading shading = VKPT_SHADING(tri.sourceIndex);
  if ((shading.flags & kShadingHasNormals) == 0u) return vec4(ng, 0.0f);
  if (VKPT_TEXTURES)  // only ray cones read it
    curvature = TriangleCurvature(DecodeOctahedral(shading.n0), DecodeOctahedral(shading.n1),
                                  DecodeOctahedral(shading.n2), tri.e1, tri.e2);
  vec3 interpolated = InterpolatedNormal(shading, hit.b1, hit.b2);
  return abs(dot(interpolated, interpolated) - 1.0f) < 1e-3f ? vec4(interpolated, 1.0f) : vec4(ng, 0.0f);
}

// The frame the BSDF works in around the shading normal ns: its x axis along an
// anisotropic material's direction (normal_map.h's AnisotropicFrame), else any.
VKPT_FN Frame ShadingFrame(VKPT_SCENE_PARAM vec3 ns, uint sourceIndex, HitRecord hit, Material material) {
  Frame f = FrameFromNormal(ns);
  if (VKPT_ANISOTROPY && VKPT_NORMAL_MAPS && material.anisotropy > 0.0f)
    f = AnisotropicFrame(f, InterpolatedTangent(VKPT_TANGENTS_OF(sourceIndex), hit.b1, hit.b2),
                         material.anisotropyDirection);
  return f;
}

// Surfaces scatter on both sides: the geometric normal is turned to face the ray, and
// the shading normal with it. One-sided materials emit from their front face only
// (glTF's winding). Textures are read at the mip level of a ray cone `coneWidth` wide at
// the hit: colour textures for one of width `coneWidths.x`, data textures and normal maps
// for one of `coneWidths.y` (material_textures.h; 0: level 0). A clear coat has its own normal (its normal map bending
// the vertex normal, not the base's) and dims the emission beneath it (fresnel.h).
VKPT_FN SurfaceHit MakeSurfaceHit(VKPT_SCENE_PARAM Ray ray, HitRecord hit, vec2 coneWidths) {
  Triangle tri = VKPT_TRIANGLE(hit.triangle);
  SurfaceHit sh;
  sh.material = VKPT_MATERIAL(tri.material);
  float coat = sh.material.clearcoat;  // before its texture: EmitterCoat reads that at level 0
  bool coated = VKPT_CLEARCOAT && coat > 0.0f;
  sh.curvature = 0.0f;
  vec3 ng = normalize(cross(tri.e1, tri.e2));
  // The texture coordinates are read once, for the material's textures and its normal maps.
  vec4 normalTexel = vec4(0.0f), coatTexel = vec4(0.0f);
  if (VKPT_TEXTURES && (sh.material.flags & kMaterialTextured) != 0u) {
    TriangleUVs uvs = VKPT_UVS_OF(tri.sourceIndex);
    float cosTheta = dot(ng, ray.dir);
    vec2 footprints = vec2(FootprintLod(coneWidths.x, cosTheta, tri.e1, tri.e2),
                           FootprintLod(coneWidths.y, cosTheta, tri.e1, tri.e2));
    ApplyMaterialTextures(VKPT_SCENE_ARG sh.material, tri.material, uvs, hit.b1, hit.b2, footprints);
    if (VKPT_NORMAL_MAPS) {
      normalTexel = NormalMapTexel(VKPT_SCENE_ARG tri.material, kSlotNormal, uvs, hit.b1, hit.b2, footprints.y);
      if (coated)
        coatTexel =
            NormalMapTexel(VKPT_SCENE_ARG tri.material, kSlotClearcoatNormal, uvs, hit.b1, hit.b2, footprints.y);
    }
  }
  if (VKPT_VERTEX_COLORS)
    sh.material.baseColor *= vec3(InterpolatedColor(VKPT_VERTEX_COLORS_OF(tri.sourceIndex), hit.b1, hit.b2));
  sh.light = tri.light;
  bool frontFace = dot(ng, ray.dir) < 0.0f;
  sh.frontFace = frontFace;
  sh.ng = frontFace ? ng : -ng;
  sh.emits = frontFace || (sh.material.flags & kMaterialDoubleSided) != 0u;
  sh.p = tri.v0 + hit.b1 * tri.e1 + hit.b2 * tri.e2;
  // The shading normals on the front side: interpolated vertex normals, bent by the
  // normal maps; the face normal where there are neither.
  vec4 n = VertexNormal(VKPT_SCENE_ARG tri, hit, ng, sh.curvature);
  vec4 nc = n;
  if (normalTexel.w > 0.0f || coatTexel.w > 0.0f) {
    vec4 tangent = InterpolatedTangent(VKPT_TANGENTS_OF(tri.sourceIndex), hit.b1, hit.b2);
    if (coatTexel.w > 0.0f)
      nc = vec4(PerturbedNormal(vec3(nc), tangent, vec3(coatTexel), sh.material.clearcoatNormalScale), 1.0f);
    if (normalTexel.w > 0.0f)
      n = vec4(PerturbedNormal(vec3(n), tangent, vec3(normalTexel), sh.material.normalScale), 1.0f);
  }
  // A flat surface needs no adaptation: the mirror direction of any ωo above it is above it.
  vec3 ns = n.w > 0.0f ? AdaptShadingNormal(frontFace ? vec3(n) : -vec3(n), sh.ng, -ray.dir) : sh.ng;
  sh.frame = ShadingFrame(VKPT_SCENE_ARG ns, tri.sourceIndex, hit, sh.material);
  sh.coatNormal = ns;
  if (coated) {
    sh.coatNormal = nc.w > 0.0f ? AdaptShadingNormal(frontFace ? vec3(nc) : -vec3(nc), sh.ng, -ray.dir) : sh.ng;
    coat = EmitterCoat(VKPT_SCENE_ARG coat, sh.material.flags, tri.material, tri.sourceIndex, hit.b1, hit.b2);
    sh.material.emission *= CoatTransmittance(coat, dot(sh.ng, ray.dir));
  }
  return sh;
}

VKPT_END_NAMESPACE

#endif

// Texture level of detail by ray cones (Akenine-Möller et al. 2021, "Improved Shader and
// Texture Level of Detail Using Ray Cones", JCGT 10(1); Ray Tracing Gems ch. 20, 2019).
//
// Each path carries a cone around its ray: its width where the ray starts and its spread
// angle (small-angle approximations throughout: width' = width + spread · t). The camera
// gives it one pixel's spread (perspective) or width (orthographic). At a hit the cone's
// footprint on the triangle, in texels, picks the mip level:
//   λ = log2(width / |cos θ|) + ½ log2(texel area / world area of the triangle),
// the texel area counting the texture's size, the TEXCOORD set and KHR_texture_transform.
// Scattering widens the cone by the surface's curvature (twice the normal's turn over the
// cone's width, as a curved mirror does; refraction is given the same, a simplification)
// and by the BSDF: a diffuse bounce adds a fixed
// kDiffuseSpread, a glossy one less where its value is higher (the OptiX Toolkit's
// heuristic: NVIDIA, "Ray Cones", optix-toolkit/ShaderUtil).
//
// Mip levels are a prefilter, which a path tracer's samples would otherwise do by
// averaging: the image converges to the filtered texture, not the point-sampled one.
// Lookups whose two estimators must agree exactly read level 0 (kLevelZero): emission
// (light sampling has no cone) and alpha (camera and shadow rays must see one surface).
#ifndef VKPT_RAY_CONE_H
#define VKPT_RAY_CONE_H
#include "prelude.h"  // first, as in every shared header

#include "layout.h"
#include "sampling.h"

VKPT_BEGIN_NAMESPACE

// A footprint that reads level 0.
const float kLevelZero = -1.0e30f;
// The spread a diffuse bounce adds, in radians (the OptiX Toolkit's s_max).
const float kDiffuseSpread = 0.25f;
// The spread and width of a camera ray's cone, in radians and scene units.
VKPT_FN vec2 CameraCone(FrameParams params) {
  // tanHalfFovY / height is half a pixel's angle (perspective) or width (orthographic).
  float pixel = 2.0f * params.tanHalfFovY / float(params.height);
  return params.orthographic != 0u ? vec2(0.0f, pixel) : vec2(pixel, 0.0f);
}

VKPT_FN float ConeWidthAt(float width, float spread, float t) { return abs(width + spread * t); }

// The part of λ that every texture of a hit shares: for a cone `width` wide arriving at
// cosine `cosTheta` on the triangle with edges e1, e2. kLevelZero for a point (width 0).
VKPT_FN float FootprintLod(float width, float cosTheta, vec3 e1, vec3 e2) {
  if (!(width > 0.0f)) return kLevelZero;
  vec3 c = cross(e1, e2);  // |c| is twice the triangle's area
  return log2(width) - log2(max(abs(cosTheta), 1e-4f)) - 0.25f * log2(dot(c, c));
}

// λ for the texture `tex`, read through `ref`, on a triangle with texture coordinates
// `uvs`: the footprint plus half the log of the triangle's area in texels (twice it, as
// FootprintLod takes twice the world area: the factors cancel).
VKPT_FN float TextureLod(float footprint, TextureRef ref, Texture tex, TriangleUVs uvs) {
  vec2 a = ref.texCoord == 0u ? uvs.uv00 : uvs.uv10;
  vec2 d1 = (ref.texCoord == 0u ? uvs.uv01 : uvs.uv11) - a;
  vec2 d2 = (ref.texCoord == 0u ? uvs.uv02 : uvs.uv12) - a;
  float uvCross = abs(d1.x * d2.y - d1.y * d2.x) * abs(ref.m00 * ref.m11 - ref.m01 * ref.m10);
  return footprint + 0.5f * log2(uvCross * float(tex.width) * float(tex.height));
}

// The curvature of a triangle with vertex normals n0, n1, n2 and edges e1 = v1 − v0,
// e2 = v2 − v0: the turn of the normal per unit length along each edge, the smallest in
// magnitude of the three, or 0 where they disagree in sign (a saddle).
VKPT_FN float EdgeCurvature(vec3 na, vec3 nb, vec3 ab) { return dot(nb - na, ab) / dot(ab, ab); }

VKPT_FN float TriangleCurvature(vec3 n0, vec3 n1, vec3 n2, vec3 e1, vec3 e2) {
  float k01 = EdgeCurvature(n0, n1, e1);
  float k02 = EdgeCurvature(n0, n2, e2);
  float k12 = EdgeCurvature(n1, n2, e2 - e1);
  if ((k01 < 0.0f || k02 < 0.0f || k12 < 0.0f) && (k01 > 0.0f || k02 > 0.0f || k12 > 0.0f)) return 0.0f;
  float k = abs(k01) < abs(k02) ? k01 : k02;
  return abs(k12) < abs(k) ? k12 : k;
}

// The spread after scattering, `width` wide, off a surface of curvature `curvature` into
// a direction where the BSDF's largest component is `f`.
VKPT_FN float ScatteredSpread(float spread, float width, float curvature, float f) {
  return spread + 2.0f * curvature * width + kDiffuseSpread * min(1.0f, 1.0f / (kPi * f));
}

VKPT_END_NAMESPACE

#endif

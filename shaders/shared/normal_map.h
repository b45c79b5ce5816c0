// Normal maps (glTF 2.0 §3.9.3, normalTexture): the texture holds a unit normal in the
// tangent space of the surface, (T, B, N) with T the vertex tangent (glTF TANGENT, or
// MikkTSpace tangents the loader generated), B = w · N × T and N the shading normal;
// x and y are scaled by normalTexture.scale. The same tangent space orients
// KHR_materials_anisotropy's lobe (AnisotropicFrame).
#ifndef VKPT_NORMAL_MAP_H
#define VKPT_NORMAL_MAP_H
#include "prelude.h"  // first, as in every shared header

#include "layout.h"
#include "sampling.h"
#include "shading_normal.h"

VKPT_BEGIN_NAMESPACE

// The tangent at barycentrics (b1, b2), not normalized, with w = ±1 the sign of the
// interpolated bitangent signs (they agree across a triangle whose UVs are not folded);
// 0 where the triangle has none.
VKPT_FN vec4 InterpolatedTangent(TriangleTangents t, float b1, float b2) {
  if ((t.signs & kTangentsMissing) != 0u) return vec4(0.0f);
  float b0 = 1.0f - b1 - b2;
  vec3 v = b0 * DecodeOctahedral(t.t0) + b1 * DecodeOctahedral(t.t1) + b2 * DecodeOctahedral(t.t2);
  float w = b0 * ((t.signs & 1u) != 0u ? -1.0f : 1.0f) + b1 * ((t.signs & 2u) != 0u ? -1.0f : 1.0f) +
            b2 * ((t.signs & 4u) != 0u ? -1.0f : 1.0f);
  return vec4(v, w < 0.0f ? -1.0f : 1.0f);
}

// The unit normal the map's `texel` (RGB in [0, 1]) gives around the unit normal n: the
// tangent made orthogonal to n (Gram–Schmidt, since the two were interpolated apart), the
// tangent-space vector 2·texel − 1 with x, y times `scale`, normalized (the spec's
// scaledNormal). Where no tangent is left (none given, or one parallel to n) n stays.
VKPT_FN vec3 PerturbedNormal(vec3 n, vec4 tangent, vec3 texel, float scale) {
  vec3 t = vec3(tangent) - dot(vec3(tangent), n) * n;
  float t2 = dot(t, t);
  if (!(t2 > 1e-12f)) return n;
  t = t / sqrt(t2);
  vec3 b = tangent.w * cross(n, t);
  vec3 m = texel * 2.0f - 1.0f;
  vec3 p = m.x * scale * t + m.y * scale * b + m.z * n;
  float p2 = dot(p, p);
  return p2 > 1e-12f ? p / sqrt(p2) : n;
}

// The shading frame turned about its normal so that its x axis is the anisotropy's
// direction (KHR_materials_anisotropy; microfacet.h stretches the lobe along x):
// `direction` in the tangent space of `tangent` (xyz, and w the bitangent's sign,
// bitangent = w n × t as glTF defines it), projected on the shading plane. Without a
// tangent (w = 0: none given and none generated, no texture coordinates) the frame keeps
// its own, arbitrary but fixed x axis.
VKPT_FN Frame AnisotropicFrame(Frame f, vec4 tangent, vec2 direction) {
  if (tangent.w == 0.0f) return f;
  vec3 t = vec3(tangent);
  vec3 a = direction.x * t + direction.y * (tangent.w * cross(f.n, t));
  a -= f.n * dot(a, f.n);
  float length2 = dot(a, a);
  if (!(length2 > 1e-12f)) return f;
  f.t = a * inversesqrt(length2);
  f.b = cross(f.n, f.t);
  return f;
}

VKPT_END_NAMESPACE

#endif

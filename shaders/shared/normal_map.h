// Normal maps (glTF 2.0 §3.9.3, normalTexture): the texture holds a unit normal in the
// tangent space of the surface, (T, B, N) with T the vertex tangent (glTF TANGENT, or
// MikkTSpace tangents the loader generated), B = w · N × T and N the shading normal;
// x and y are scaled by normalTexture.scale.
#ifndef VKPT_NORMAL_MAP_H
#define VKPT_NORMAL_MAP_H
#include "prelude.h"  // first, as in every shared header

#include "layout.h"
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

VKPT_END_NAMESPACE

#endif

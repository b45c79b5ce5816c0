// Smooth-shading normals: the vertex normals of a TriangleShading record, decoded from
// their octahedral encoding and interpolated across the triangle.
//
// Octahedral encoding (Cigolle et al. 2014, "A Survey of Efficient Representations for
// Independent Unit Vectors", JCGT 3(2)): a unit vector is projected onto the octahedron
// |x| + |y| + |z| = 1, whose lower half is folded over the upper one, and the resulting
// square [-1,1]² is stored as two snorm16 values. 4 bytes a normal instead of 12, with an
// angular error of a few 1e-5 rad. The encoder is host-side (host/render/octahedral.h).
#ifndef VKPT_SHADING_NORMAL_H
#define VKPT_SHADING_NORMAL_H
#include "prelude.h"  // first, as in every shared header

#include "layout.h"

VKPT_BEGIN_NAMESPACE

// ±1 with +1 for zero, so that the fold of the lower half never collapses to a line.
VKPT_FN float SignNotZero(float x) { return x >= 0.0f ? 1.0f : -1.0f; }

// The unit vector of an octahedral code (two snorm16: x in the low 16 bits).
VKPT_FN vec3 DecodeOctahedral(uint packed) {
  vec2 e = unpackSnorm2x16(packed);
  vec3 v = vec3(e.x, e.y, 1.0f - abs(e.x) - abs(e.y));
  // The lower hemisphere was folded outward across the square's diagonals: unfold it.
  if (v.z < 0.0f) v = vec3((1.0f - abs(e.y)) * SignNotZero(e.x), (1.0f - abs(e.x)) * SignNotZero(e.y), v.z);
  return normalize(v);
}

// The shading normal at barycentrics (b1, b2) of a triangle with kShadingHasNormals: the
// vertex normals interpolated linearly (Phong shading), renormalized.
VKPT_FN vec3 InterpolatedNormal(TriangleShading s, float b1, float b2) {
  return normalize((1.0f - b1 - b2) * DecodeOctahedral(s.n0) + b1 * DecodeOctahedral(s.n1) +
                   b2 * DecodeOctahedral(s.n2));
}

VKPT_END_NAMESPACE

#endif

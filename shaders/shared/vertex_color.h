// Vertex colours (glTF COLOR_0, spec §3.7.2.1): a TriangleColors record decoded and
// interpolated across the triangle. They multiply the material's base colour (spec
// §3.9.2), which KHR_materials_unlit shows as is.
#ifndef VKPT_VERTEX_COLOR_H
#define VKPT_VERTEX_COLOR_H
#include "prelude.h"  // first, as in every shared header

#include "layout.h"

VKPT_BEGIN_NAMESPACE

// Two unorm16 values, the first in the low bits. Written out rather than with
// unpackUnorm2x16, whose C++ (GLM: a multiplication by 1/65535) and GLSL implementations
// may round differently.
VKPT_FN vec2 DecodeUnorm16Pair(uint packed) {
  return vec2(float(packed & 0xFFFFu) / 65535.0f, float(packed >> 16u) / 65535.0f);
}

VKPT_FN vec4 DecodeVertexColor(uint rg, uint ba) {
  vec2 a = DecodeUnorm16Pair(rg);
  vec2 b = DecodeUnorm16Pair(ba);
  return vec4(a.x, a.y, b.x, b.y);
}

// The colour at barycentrics (b1, b2): the vertex colours interpolated linearly.
VKPT_FN vec4 InterpolatedColor(TriangleColors c, float b1, float b2) {
  return (1.0f - b1 - b2) * DecodeVertexColor(c.rg0, c.ba0) + b1 * DecodeVertexColor(c.rg1, c.ba1) +
         b2 * DecodeVertexColor(c.rg2, c.ba2);
}

VKPT_END_NAMESPACE

#endif

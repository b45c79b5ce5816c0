#version 460
// Test kernel: one texture lookup (shared/texture.h's SampleTexture) per invocation, with
// the texture buffers of a RenderScene, so that tests can compare every result bit for
// bit with the C++ build of the same header (tests/test_texture_gpu.cpp).
#extension GL_GOOGLE_include_directive : require
#include "shared/layout.h"

layout(local_size_x = 64) in;
// Whether the texels are split over two buffers at texelSplit (scene_fetch.glsl).
layout(constant_id = 0) const uint kTwoTexelBuffers = 0u;
#define VKPT_TWO_TEXEL_BUFFERS (kTwoTexelBuffers != 0u)
// The lookup as one straight line (shared/texture.h), or with the branches that skip work.
layout(constant_id = 1) const uint kMaskedBranches = 0u;
#define VKPT_MASKED_BRANCHES (kMaskedBranches != 0u)
layout(push_constant) uniform Push { uint texelSplit; };

#define VKPT_SCENE_PARAM
#define VKPT_SCENE_ARG
#define VKPT_TEXTURE(i) FetchTexture(i)
#define VKPT_TEXEL_WORD(i) FetchTexelWord(i)
#define VKPT_TEXEL_DECODE(i) FetchTexelDecode(i)
#include "scene_fetch.glsl"
#include "shared/texture.h"

struct TextureLookup {
  vec2 uv;
  float lod;
  uint texture;
  uint srgb;  // the texture's RGB read as colour (1) or data (0)
};
layout(std430, binding = 30) readonly buffer In { TextureLookup lookups[]; };
layout(std430, binding = 31) writeonly buffer Out { vec4 results[]; };

void main() {
  gTexelSplit = texelSplit;
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(lookups.length())) return;
  TextureLookup l = lookups[i];
  Texture t = FetchTexture(l.texture);
  results[i] = SampleTexture(t, l.uv, l.lod, l.srgb != 0u);
}

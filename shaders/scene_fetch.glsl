// The scene for the shaders: triangles, BVH nodes, materials, lights, shading normals,
// vertex colours, texture coordinates, textures and the environment map, read from
// uniform texel buffers of RGBA32UI texels (16 bytes; kTexelsPer* per record, the std430
// layouts of gpu_records.def byte for byte, by the generated gpu_fetch.glsl).
//
// Why texels and not storage-buffer structs: lavapipe (Mesa 22.3) has no gathers for
// either. It reads a 16-byte texel lane by lane — eight scalar loads and a transpose,
// about 45 instructions per fetch — and a storage-buffer struct with a loop over the 8
// SIMD lanes and a bounds-checked scalar load per component; the texel fetches measured
// faster (docs/design-notes.md, "The scene in texel buffers"). Texel buffers also reach
// further: 2^27 texels (2 GiB) on lavapipe against 128 MiB per storage buffer. An
// integer format keeps every bit (skip links, float bits) exactly.
#ifndef VKPT_SCENE_FETCH_GLSL
#define VKPT_SCENE_FETCH_GLSL
#include "shared/layout.h"

layout(binding = kBindingTriangles) uniform usamplerBuffer triangleTexels;
layout(binding = kBindingTrianglesHigh) uniform usamplerBuffer triangleTexelsHigh;
layout(binding = kBindingNodes) uniform usamplerBuffer nodeTexels;
layout(binding = kBindingMaterials) uniform usamplerBuffer materialTexels;
layout(binding = kBindingLights) uniform usamplerBuffer lightTexels;
layout(binding = kBindingAlbedoTables) uniform usamplerBuffer albedoTableTexels;
layout(binding = kBindingShading) uniform usamplerBuffer shadingTexels;
layout(binding = kBindingVertexColors) uniform usamplerBuffer colorTexels;
layout(binding = kBindingVertexUVs) uniform usamplerBuffer uvTexels;
layout(binding = kBindingVertexUVsHigh) uniform usamplerBuffer uvTexelsHigh;
layout(binding = kBindingTangents) uniform usamplerBuffer tangentTexels;
layout(binding = kBindingMaterialTextures) uniform usamplerBuffer textureRefTexels;
layout(binding = kBindingTextures) uniform usamplerBuffer textureTexels;
layout(binding = kBindingTexels) uniform usamplerBuffer texelWords;
layout(binding = kBindingTexelsHigh) uniform usamplerBuffer texelWordsHigh;
layout(binding = kBindingTexelDecode) uniform usamplerBuffer texelDecodeTexels;
layout(binding = kBindingEnvRadiance) uniform usamplerBuffer envRadianceTexels;
layout(binding = kBindingEnvDistribution) uniform usamplerBuffer envDistributionTexels;

// Element k of an array of three-texel structs that may continue in a second texel
// buffer: from element `split` on in `high`, when `two`. `two` is a specialization
// constant of the including shader, so with one buffer the second branch compiles away
// (lavapipe would otherwise run both fetches).
void FetchThreeTexels(usamplerBuffer low, usamplerBuffer high, bool two, uint split, uint k, out uvec4 t[3]) {
  if (two && k >= split) {
    int i = int(3u * (k - split));
    t[0] = texelFetch(high, i);
    t[1] = texelFetch(high, i + 1);
    t[2] = texelFetch(high, i + 2);
  } else {
    int i = int(3u * k);
    t[0] = texelFetch(low, i);
    t[1] = texelFetch(low, i + 1);
    t[2] = texelFetch(low, i + 2);
  }
}

// The triangles, and the texture coordinates, in two buffers when one cannot hold them
// (VKPT_TWO_TRIANGLE_BUFFERS, VKPT_TWO_UV_BUFFERS); main() sets the splits.
#ifndef VKPT_TWO_TRIANGLE_BUFFERS
#define VKPT_TWO_TRIANGLE_BUFFERS false
#endif
#ifndef VKPT_TWO_UV_BUFFERS
#define VKPT_TWO_UV_BUFFERS false
#endif
uint gTriangleSplit = 0xFFFFFFFFu;
uint gUvSplit = 0xFFFFFFFFu;

#ifndef VKPT_IRIDESCENCE
#define VKPT_IRIDESCENCE true
#endif
#ifndef VKPT_ANISOTROPY
#define VKPT_ANISOTROPY true
#endif
#ifndef VKPT_DISPERSION
#define VKPT_DISPERSION true
#endif

// The light tree's nodes follow the lights in the same texel buffer, from texel
// gLightNodeBase on (kTexelsPerLight · FrameParams::lightCount, set by main()).
uint gLightNodeBase = 0u;

// Fetch<Record>(i) of every record read from texels, generated from gpu_records.def.
#include "gpu_fetch.glsl"

// Pair k of shared/albedo_tables.h's kAlbedoTables (two pairs per texel).
vec2 FetchAlbedoPair(uint k) {
  uvec4 t = texelFetch(albedoTableTexels, int(k >> 1u));
  return uintBitsToFloat((k & 1u) == 0u ? t.xy : t.zw);
}

// Word i of the texture store (four per texel). The store may be in two buffers
// (VKPT_TWO_TEXEL_BUFFERS, a specialization constant of the including shader): texels
// from gTexelSplit on (FrameParams::texelSplit, set by main()) are in the second. With
// one, the second branch compiles away.
#ifndef VKPT_TWO_TEXEL_BUFFERS
#define VKPT_TWO_TEXEL_BUFFERS false
#endif
uint gTexelSplit = 0xFFFFFFFFu;

uint FetchTexelWord(uint i) {
  uint t = i >> 2u;
  if (VKPT_TWO_TEXEL_BUFFERS && t >= gTexelSplit) return texelFetch(texelWordsHigh, int(t - gTexelSplit))[i & 3u];
  return texelFetch(texelWords, int(t))[i & 3u];
}

float FetchTexelDecode(uint i) { return uintBitsToFloat(texelFetch(texelDecodeTexels, int(i >> 2u))[i & 3u]); }

vec4 FetchEnvTexel(uint i) { return uintBitsToFloat(texelFetch(envRadianceTexels, int(i))); }

float FetchEnvCdf(uint i) {
  return uintBitsToFloat(texelFetch(envDistributionTexels, int(i / kEnvCdfsPerTexel))[i % kEnvCdfsPerTexel]);
}

#endif

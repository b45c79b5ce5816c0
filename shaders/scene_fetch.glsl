// The scene for the shaders: triangles, BVH nodes, materials, lights, shading normals,
// vertex colours, texture coordinates, textures and the environment map read from uniform texel buffers of RGBA32UI
// texels (16 bytes; kTexelsPer* per struct, the std430 layouts of shared/layout.h byte
// for byte).
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

WideBvhNode FetchWideNode(uint i) {
  int t = int(kTexelsPerWideNode * i);
  uvec4 a = texelFetch(nodeTexels, t);
  WideBvhNode n;
  n.origin = uintBitsToFloat(a.xyz);
  n.exponents = a.w;
  n.lo = texelFetch(nodeTexels, t + 1);
  n.hi = texelFetch(nodeTexels, t + 2);
  n.child = texelFetch(nodeTexels, t + 3);
  return n;
}

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

Triangle FetchTriangle(uint k) {
  uvec4 x[3];
  FetchThreeTexels(triangleTexels, triangleTexelsHigh, VKPT_TWO_TRIANGLE_BUFFERS, gTriangleSplit, k, x);
  Triangle t;
  t.v0 = uintBitsToFloat(x[0].xyz);
  t.material = x[0].w;
  t.e1 = uintBitsToFloat(x[1].xyz);
  t.sourceIndex = x[1].w;
  t.e2 = uintBitsToFloat(x[2].xyz);
  t.light = x[2].w;
  return t;
}

#ifndef VKPT_IRIDESCENCE
#define VKPT_IRIDESCENCE true
#endif
#ifndef VKPT_ANISOTROPY
#define VKPT_ANISOTROPY true
#endif
#ifndef VKPT_DISPERSION
#define VKPT_DISPERSION true
#endif

Material FetchMaterial(uint m) {
  uvec4 a = texelFetch(materialTexels, int(kTexelsPerMaterial * m));
  uvec4 b = texelFetch(materialTexels, int(kTexelsPerMaterial * m + 1u));
  uvec4 c = texelFetch(materialTexels, int(kTexelsPerMaterial * m + 2u));
  uvec4 d = texelFetch(materialTexels, int(kTexelsPerMaterial * m + 3u));
  uvec4 e = texelFetch(materialTexels, int(kTexelsPerMaterial * m + 4u));
  uvec4 f = texelFetch(materialTexels, int(kTexelsPerMaterial * m + 5u));
  uvec4 g = texelFetch(materialTexels, int(kTexelsPerMaterial * m + 6u));
  uvec4 h = texelFetch(materialTexels, int(kTexelsPerMaterial * m + 7u));
  // The film's and the anisotropy's texels only where some material has them
  // (scene_constants.glsl).
  uvec4 i = VKPT_IRIDESCENCE ? texelFetch(materialTexels, int(kTexelsPerMaterial * m + 8u)) : uvec4(0u);
  uvec4 j = VKPT_ANISOTROPY || VKPT_DISPERSION ? texelFetch(materialTexels, int(kTexelsPerMaterial * m + 9u)) : uvec4(0u);
  Material mat;
  mat.baseColor = uintBitsToFloat(a.xyz);
  mat.metallic = uintBitsToFloat(a.w);
  mat.emission = uintBitsToFloat(b.xyz);
  mat.roughness = uintBitsToFloat(b.w);
  mat.specularColor = uintBitsToFloat(c.xyz);
  mat.specular = uintBitsToFloat(c.w);
  mat.attenuation = uintBitsToFloat(d.xyz);
  mat.ior = uintBitsToFloat(d.w);
  mat.transmission = uintBitsToFloat(e.x);
  mat.flags = e.y;
  mat.normalScale = uintBitsToFloat(e.z);
  mat.alpha = uintBitsToFloat(e.w);
  mat.alphaCutoff = uintBitsToFloat(f.x);
  mat.clearcoat = uintBitsToFloat(f.y);
  mat.clearcoatRoughness = uintBitsToFloat(f.z);
  mat.clearcoatNormalScale = uintBitsToFloat(f.w);
  mat.sheenColor = uintBitsToFloat(g.xyz);
  mat.sheenRoughness = uintBitsToFloat(g.w);
  mat.diffuseTransmissionColor = uintBitsToFloat(h.xyz);
  mat.diffuseTransmission = uintBitsToFloat(h.w);
  mat.iridescence = uintBitsToFloat(i.x);
  mat.iridescenceIor = uintBitsToFloat(i.y);
  mat.iridescenceThicknessMin = uintBitsToFloat(i.z);
  mat.iridescenceThickness = uintBitsToFloat(i.w);
  mat.anisotropy = uintBitsToFloat(j.x);
  mat.dispersion = uintBitsToFloat(j.y);
  mat.anisotropyDirection = uintBitsToFloat(j.zw);
  return mat;
}

Light FetchLight(uint i) {
  uvec4 a = texelFetch(lightTexels, int(kTexelsPerLight * i));
  uvec4 b = texelFetch(lightTexels, int(kTexelsPerLight * i + 1u));
  uvec4 c = texelFetch(lightTexels, int(kTexelsPerLight * i + 2u));
  uvec4 d = texelFetch(lightTexels, int(kTexelsPerLight * i + 3u));
  Light l;
  l.position = uintBitsToFloat(a.xyz);
  l.triangle = a.w;
  l.direction = uintBitsToFloat(b.xyz);
  l.type = b.w;
  l.radiance = uintBitsToFloat(c.xyz);
  l.extent = uintBitsToFloat(c.w);
  l.cdf = uintBitsToFloat(d.x);
  l.pmf = uintBitsToFloat(d.y);
  l.cosOuter = uintBitsToFloat(d.z);
  l.cosInner = uintBitsToFloat(d.w);
  return l;
}

// The binary search over the CDF reads one texel per step.
float FetchLightCdf(uint i) { return uintBitsToFloat(texelFetch(lightTexels, int(kTexelsPerLight * i + 3u)).x); }

// The light tree's nodes follow the lights in the same texel buffer, from texel
// gLightNodeBase on (kTexelsPerLight · FrameParams::lightCount, set by main()).
uint gLightNodeBase = 0u;

LightTreeNode FetchLightNode(uint i) {
  int base = int(gLightNodeBase + kTexelsPerLightNode * i);
  uvec4 a = texelFetch(lightTexels, base);
  uvec4 b = texelFetch(lightTexels, base + 1);
  uvec4 c = texelFetch(lightTexels, base + 2);
  LightTreeNode n;
  n.center = uintBitsToFloat(a.xyz);
  n.radius = uintBitsToFloat(a.w);
  n.axis = uintBitsToFloat(b.xyz);
  n.intensity = uintBitsToFloat(b.w);
  n.cosThetaO = uintBitsToFloat(c.x);
  n.sinThetaO = uintBitsToFloat(c.y);
  n.cosThetaE = uintBitsToFloat(c.z);
  n.split = c.w;
  return n;
}

// Pair k of shared/albedo_tables.h's kAlbedoTables (two pairs per texel).
vec2 FetchAlbedoPair(uint k) {
  uvec4 t = texelFetch(albedoTableTexels, int(k >> 1u));
  return uintBitsToFloat((k & 1u) == 0u ? t.xy : t.zw);
}

// i: a Triangle's sourceIndex (the triangle's index in the Scene).
TriangleShading FetchShading(uint i) {
  uvec4 a = texelFetch(shadingTexels, int(kTexelsPerShading * i));
  TriangleShading s;
  s.n0 = a.x;
  s.n1 = a.y;
  s.n2 = a.z;
  s.flags = a.w;
  return s;
}

// i: a Triangle's sourceIndex.
TriangleColors FetchColors(uint i) {
  uvec4 a = texelFetch(colorTexels, int(kTexelsPerColors * i));
  uvec4 b = texelFetch(colorTexels, int(kTexelsPerColors * i + 1u));
  TriangleColors c;
  c.rg0 = a.x;
  c.ba0 = a.y;
  c.rg1 = a.z;
  c.ba1 = a.w;
  c.rg2 = b.x;
  c.ba2 = b.y;
  c.pad0 = b.z;
  c.pad1 = b.w;
  return c;
}

// i: a Triangle's sourceIndex.
TriangleUVs FetchUVs(uint i) {
  uvec4 x[3];
  FetchThreeTexels(uvTexels, uvTexelsHigh, VKPT_TWO_UV_BUFFERS, gUvSplit, i, x);
  TriangleUVs t;
  t.uv00 = uintBitsToFloat(x[0].xy);
  t.uv01 = uintBitsToFloat(x[0].zw);
  t.uv02 = uintBitsToFloat(x[1].xy);
  t.uv10 = uintBitsToFloat(x[1].zw);
  t.uv11 = uintBitsToFloat(x[2].xy);
  t.uv12 = uintBitsToFloat(x[2].zw);
  return t;
}

// i: a Triangle's sourceIndex.
TriangleTangents FetchTangents(uint i) {
  uvec4 a = texelFetch(tangentTexels, int(kTexelsPerTangents * i));
  TriangleTangents t;
  t.t0 = a.x;
  t.t1 = a.y;
  t.t2 = a.z;
  t.signs = a.w;
  return t;
}

TextureRef FetchTextureRef(uint i) {
  uvec4 a = texelFetch(textureRefTexels, int(kTexelsPerTextureRef * i));
  uvec4 b = texelFetch(textureRefTexels, int(kTexelsPerTextureRef * i + 1u));
  TextureRef r;
  r.texture = a.x;
  r.texCoord = a.y;
  r.m00 = uintBitsToFloat(a.z);
  r.m01 = uintBitsToFloat(a.w);
  r.m02 = uintBitsToFloat(b.x);
  r.m10 = uintBitsToFloat(b.y);
  r.m11 = uintBitsToFloat(b.z);
  r.m12 = uintBitsToFloat(b.w);
  return r;
}

Texture FetchTexture(uint i) {
  uvec4 a = texelFetch(textureTexels, int(i));
  Texture t;
  t.offset = a.x;
  t.width = a.y;
  t.height = a.z;
  t.mode = a.w;
  return t;
}

// Word i of the texture store (four per texel).
// The texel store in two buffers (VKPT_TWO_TEXEL_BUFFERS, a specialization constant of the
// including shader): texels from gTexelSplit on (FrameParams::texelSplit, set by main())
// are in the second. With one, the second branch compiles away.
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

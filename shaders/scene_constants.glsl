// The scene constants of the kernels that run the shared estimator (pathtrace.comp,
// aov.comp): specialization constants the host sets from what the scene has
// (vk_renderer.cpp, Specialization), and the scene access the shared headers expect
// (shared/path.h), through scene_fetch.glsl.
#ifndef VKPT_SCENE_CONSTANTS_GLSL
#define VKPT_SCENE_CONSTANTS_GLSL

// What the scene has, set by the host, so that lavapipe's compiler drops the code of what
// it lacks (it runs an if's body even when no lane takes it).
// The light types of the light table, bit 1 << kLight* (0: no lights): see shared/lights.h.
layout(constant_id = 0) const uint kSceneLightTypes = 0xFFFFFFFFu;
#define VKPT_LIGHT_TYPES kSceneLightTypes
// 0 when every material a triangle uses is Lambertian: see shared/bsdf.h.
layout(constant_id = 1) const uint kSceneHasGlossy = 1u;
#define VKPT_GLOSSY_MATERIALS (kSceneHasGlossy != 0u)
// 0 when no triangle has vertex normals: see shared/shading_frame.h.
layout(constant_id = 2) const uint kSceneHasSmoothNormals = 1u;
#define VKPT_SMOOTH_NORMALS (kSceneHasSmoothNormals != 0u)
// 0 without an environment map: see shared/environment.h.
layout(constant_id = 3) const uint kSceneHasEnvironmentMap = 1u;
#define VKPT_ENVIRONMENT_MAP (kSceneHasEnvironmentMap != 0u)
// 0 when no triangle has vertex colours: see shared/shading_frame.h.
layout(constant_id = 4) const uint kSceneHasVertexColors = 1u;
#define VKPT_VERTEX_COLORS (kSceneHasVertexColors != 0u)
// 0 when no triangle's material bounds a volume: see shared/path.h.
layout(constant_id = 5) const uint kSceneHasVolumes = 1u;
#define VKPT_VOLUMES (kSceneHasVolumes != 0u)
// 0 when no material has a texture: see shared/material_textures.h.
layout(constant_id = 6) const uint kSceneHasTextures = 1u;
#define VKPT_TEXTURES (kSceneHasTextures != 0u)
// 0 when no material has a normal texture: see shared/shading_frame.h.
layout(constant_id = 7) const uint kSceneHasNormalMaps = 1u;
#define VKPT_NORMAL_MAPS (kSceneHasNormalMaps != 0u)
// 0 when no triangle's material is alpha MASK or BLEND: see shared/alpha.h.
layout(constant_id = 8) const uint kSceneHasAlpha = 1u;
#define VKPT_ALPHA (kSceneHasAlpha != 0u)
// 0 when no material has a transmission, specular or specular colour texture: see
// shared/material_textures.h.
layout(constant_id = 9) const uint kSceneHasExtensionTextures = 1u;
#define VKPT_EXTENSION_TEXTURES (kSceneHasExtensionTextures != 0u)
// 1 when the texel store needs two texel buffers: see scene_fetch.glsl.
layout(constant_id = 10) const uint kSceneHasTwoTexelBuffers = 0u;
#define VKPT_TWO_TEXEL_BUFFERS (kSceneHasTwoTexelBuffers != 0u)
// 1 when the triangles need two texel buffers: see scene_fetch.glsl.
layout(constant_id = 11) const uint kSceneHasTwoTriangleBuffers = 0u;
#define VKPT_TWO_TRIANGLE_BUFFERS (kSceneHasTwoTriangleBuffers != 0u)
// 1 when the texture coordinates need two texel buffers: see scene_fetch.glsl.
layout(constant_id = 12) const uint kSceneHasTwoUvBuffers = 0u;
#define VKPT_TWO_UV_BUFFERS (kSceneHasTwoUvBuffers != 0u)
// 0 when no triangle's material has a clear coat: see shared/clearcoat.h.
layout(constant_id = 13) const uint kSceneHasClearcoat = 1u;
#define VKPT_CLEARCOAT (kSceneHasClearcoat != 0u)
// 0 when no triangle's material has a sheen: see shared/sheen.h.
layout(constant_id = 14) const uint kSceneHasSheen = 1u;
#define VKPT_SHEEN (kSceneHasSheen != 0u)
// 0 when no triangle's material transmits diffusely: see shared/bsdf.h.
layout(constant_id = 15) const uint kSceneHasDiffuseTransmission = 1u;
#define VKPT_DIFFUSE_TRANSMISSION (kSceneHasDiffuseTransmission != 0u)
// 0 when no triangle's material is iridescent: see shared/iridescence.h.
layout(constant_id = 16) const uint kSceneHasIridescence = 1u;
#define VKPT_IRIDESCENCE (kSceneHasIridescence != 0u)
// 0 when no triangle's material is anisotropic: see shared/microfacet.h.
layout(constant_id = 17) const uint kSceneHasAnisotropy = 1u;
#define VKPT_ANISOTROPY (kSceneHasAnisotropy != 0u)
// 0 when no triangle's material is dispersive: see shared/dispersion.h.
layout(constant_id = 18) const uint kSceneHasDispersion = 1u;
#define VKPT_DISPERSION (kSceneHasDispersion != 0u)
// 1 when the device runs both sides of every branch (a CPU device: lavapipe), so that
// texture lookups are written as one straight line: see shared/texture.h.
layout(constant_id = 19) const uint kDeviceMasksBranches = 0u;
#define VKPT_MASKED_BRANCHES (kDeviceMasksBranches != 0u)
// 1 when the scene chooses among its finite lights by a light tree: see shared/light_tree.h.
layout(constant_id = 20) const uint kSceneHasLightTree = 0u;
#define VKPT_LIGHT_TREE (kSceneHasLightTree != 0u)

#define VKPT_SCENE_PARAM
#define VKPT_SCENE_ARG
#define VKPT_TRIANGLE(i) FetchTriangle(i)
#define VKPT_MATERIAL(i) FetchMaterial(i)
#define VKPT_LIGHT(i) FetchLight(i)
#define VKPT_LIGHT_CDF(i) FetchLightCdf(i)
#define VKPT_LIGHT_NODE(i) FetchLightNode(i)
#define VKPT_ALBEDO_PAIR(k) FetchAlbedoPair(k)
#define VKPT_SHADING(i) FetchShading(i)
#define VKPT_VERTEX_COLORS_OF(i) FetchColors(i)
#define VKPT_TEXTURE(i) FetchTexture(i)
#define VKPT_TEXEL_WORD(i) FetchTexelWord(i)
#define VKPT_TEXEL_DECODE(i) FetchTexelDecode(i)
#define VKPT_TEXTURE_REF(i) FetchTextureRef(i)
#define VKPT_UVS_OF(i) FetchUVs(i)
#define VKPT_TANGENTS_OF(i) FetchTangents(i)
#define VKPT_ENV_TEXEL(i) FetchEnvTexel(i)
#define VKPT_ENV_CDF(i) FetchEnvCdf(i)

#endif

// The backend contract: what a language must define before it includes shaders/shared/.
//
// The headers of shaders/shared/ are one source for two backends: GLSL (the kernels of
// shaders/) and C++ (the CPU reference, host/cpu/, and host code that samples the scene
// as the renderers do). Neither side may define more than this file lists, nor the
// estimator's side less than it requires; tests/backend_contract_test.cmake checks both
// against the table below, and the #error checks at the end stop a build that omits a
// required name before it gets to the estimator (path.h includes this file).
//
// The backends:
//   C++ estimator   shared/cpp_prelude.h, host/render/scene_access.h, host/cpu/cpu_path.h
//   GLSL estimator  shared/glsl_prelude.h, scene_constants.glsl, scene_fetch.glsl, traverse.glsl
//   C++ denoiser    shared/cpp_prelude.h, host/render/denoise.cpp
//   GLSL denoiser   shared/glsl_prelude.h, denoise.comp
// Besides the names below, both languages provide GLSL's types and built-ins that the
// headers use (vec2…uvec4, uint, dot, normalize, clamp, floatBitsToUint, …): GLSL has
// them, C++ takes them from GLM (cpp_prelude.h: using namespace glm, uint = uint32_t).
//
// One name per line: [kind] NAME meaning. Kinds: language (every backend: the prelude),
// scene and function (every estimator backend: scene access and traversal), denoise
// (every denoiser backend), capability (optional: a backend may define it first, the
// GPU as a specialization constant so that lavapipe compiles out what a scene lacks;
// otherwise the header named defaults it to "the scene may have it"), internal (a GLSL
// backend's own, read by no shared header) and test (test builds only).
//
//   [language] VKPT_FN                  qualifier of free functions: inline / nothing
//   [language] VKPT_RARE_FN             qualifier of functions few materials reach: out of line / nothing
//   [language] VKPT_INOUT(T)            a parameter read and written: T& / inout T
//   [language] VKPT_PRECISE             no FMA contraction: nothing (-ffp-contract=off) / precise
//   [language] VKPT_BEGIN_NAMESPACE     opens vkpt::shader in C++; nothing in GLSL
//   [language] VKPT_END_NAMESPACE       closes it
//   [scene] VKPT_SCENE_PARAM            the scene as a leading parameter declaration ("" in GLSL)
//   [scene] VKPT_SCENE_ARG              the matching leading argument ("" in GLSL)
//   [scene] VKPT_TRIANGLE(i)            Triangle i (layout.h)
//   [scene] VKPT_MATERIAL(i)            Material i
//   [scene] VKPT_LIGHT(i)               Light i of the light table (lights.h)
//   [scene] VKPT_LIGHT_CDF(i)           VKPT_LIGHT(i).cdf (the GPU fetches one texel for it)
//   [scene] VKPT_LIGHT_NODE(i)          LightTreeNode i of the light tree (light_tree.h)
//   [scene] VKPT_SHADING(i)             TriangleShading of triangle i (vertex normals)
//   [scene] VKPT_VERTEX_COLORS_OF(i)    TriangleColors of triangle i
//   [scene] VKPT_UVS_OF(i)              TriangleUVs of triangle i
//   [scene] VKPT_TANGENTS_OF(i)         TriangleTangents of triangle i
//   [scene] VKPT_TEXTURE_REF(i)         TextureRef i (a material's textures)
//   [scene] VKPT_TEXTURE(i)             Texture i of the texture table
//   [scene] VKPT_TEXEL_WORD(i)          word i of the texel store
//   [scene] VKPT_TEXEL_DECODE(i)        entry i of the texel decode tables
//   [scene] VKPT_ENV_TEXEL(i)           texel i of the environment map (vec4)
//   [scene] VKPT_ENV_CDF(i)             entry i of the environment map's CDFs
//   [function] TraceClosest             HitRecord TraceClosest(VKPT_SCENE_PARAM vec3 origin, vec3 dir,
//                                       float tMax, uint alphaKey): the closest hit alpha.h keeps
//   [function] TraceOccluded            bool TraceOccluded(VKPT_SCENE_PARAM …same…): any such hit
//   [capability] VKPT_LIGHT_TYPES       lights.h: the light types in the table (bit 1 << kLight*)
//   [capability] VKPT_LIGHT_TREE        light_tree.h: the scene has a light tree
//   [capability] VKPT_LIGHT_IMPORTANCES(nodes, p, n)  light_tree.h: LightNodeImportancesEach's
//                                       results, computed the backend's way (the CPU's SSE2)
//   [capability] VKPT_GLOSSY_MATERIALS  bsdf.h: some material is not Lambertian
//   [capability] VKPT_SMOOTH_NORMALS    shading_frame.h: some triangle has vertex normals
//   [capability] VKPT_ENVIRONMENT_MAP   environment.h: the scene has an environment map
//   [capability] VKPT_VERTEX_COLORS     alpha.h, shading_frame.h: some triangle has COLOR_0
//   [capability] VKPT_VOLUMES           path.h: some material bounds a volume
//   [capability] VKPT_TEXTURES          material_textures.h: some material has a texture
//   [capability] VKPT_NORMAL_MAPS       shading_frame.h: some material has a normal texture
//   [capability] VKPT_ALPHA             alpha.h: some material is alpha MASK or BLEND
//   [capability] VKPT_EXTENSION_TEXTURES  material_textures.h: textures of material extensions
//   [capability] VKPT_CLEARCOAT         clearcoat.h: some material has a clear coat
//   [capability] VKPT_SHEEN             sheen.h: some material has a sheen
//   [capability] VKPT_DIFFUSE_TRANSMISSION  bsdf.h: some material transmits diffusely
//   [capability] VKPT_IRIDESCENCE       iridescence.h: some material is iridescent
//   [capability] VKPT_ANISOTROPY        microfacet.h: some material is anisotropic
//   [capability] VKPT_DISPERSION        dispersion.h: some material is dispersive
//   [capability] VKPT_TEXEL_UNORM(b)    texture.h: byte b as b / 255, exactly rounded; default
//                                       UnormByte's arithmetic (the CPU reads its table)
//   [capability] VKPT_MASKED_BRANCHES   texture.h: the device runs both sides of every branch
//                                       (lavapipe); default false, lookups that skip work
//   [capability] VKPT_ALBEDO_PAIR(k)     albedo_tables.h: pair k of the albedo tables
//   [denoise] VKPT_DENOISE_PARAM        denoise.h: the images as a leading parameter declaration
//   [denoise] VKPT_DENOISE_ARG          the matching leading argument
//   [denoise] VKPT_DENOISE_COLOR(i)     the noisy colour of pixel i
//   [denoise] VKPT_DENOISE_GUIDE(i)     the guide (normal, depth) of pixel i
//   [denoise] VKPT_DENOISE_ALBEDO(i)    the albedo of pixel i (vec3)
//   [internal] VKPT_TWO_TRIANGLE_BUFFERS  scene_fetch.glsl: triangles in two texel buffers
//   [internal] VKPT_TWO_UV_BUFFERS      scene_fetch.glsl: texture coordinates in two
//   [internal] VKPT_TWO_TEXEL_BUFFERS   scene_fetch.glsl: the texel store in two
//   [internal] VKPT_COUNT_BOX_TESTS     traverse.glsl: count box tests (aov.comp's heat map)
//   [test] VKPT_ESTIMATOR_OVERRIDES     path.h includes a test's estimator_overrides.h (its seams)
#ifndef VKPT_BACKEND_CONTRACT_H
#define VKPT_BACKEND_CONTRACT_H

#ifndef VKPT_FN
#error "backend contract: VKPT_FN is not defined"
#endif
#ifndef VKPT_RARE_FN
#error "backend contract: VKPT_RARE_FN is not defined"
#endif
#ifndef VKPT_INOUT
#error "backend contract: VKPT_INOUT is not defined"
#endif
#ifndef VKPT_PRECISE
#error "backend contract: VKPT_PRECISE is not defined"
#endif
#ifndef VKPT_BEGIN_NAMESPACE
#error "backend contract: VKPT_BEGIN_NAMESPACE is not defined"
#endif
#ifndef VKPT_END_NAMESPACE
#error "backend contract: VKPT_END_NAMESPACE is not defined"
#endif
#ifndef VKPT_SCENE_PARAM
#error "backend contract: VKPT_SCENE_PARAM is not defined"
#endif
#ifndef VKPT_SCENE_ARG
#error "backend contract: VKPT_SCENE_ARG is not defined"
#endif
#ifndef VKPT_TRIANGLE
#error "backend contract: VKPT_TRIANGLE is not defined"
#endif
#ifndef VKPT_MATERIAL
#error "backend contract: VKPT_MATERIAL is not defined"
#endif
#ifndef VKPT_LIGHT
#error "backend contract: VKPT_LIGHT is not defined"
#endif
#ifndef VKPT_LIGHT_CDF
#error "backend contract: VKPT_LIGHT_CDF is not defined"
#endif
#ifndef VKPT_LIGHT_NODE
#error "backend contract: VKPT_LIGHT_NODE is not defined"
#endif
#ifndef VKPT_SHADING
#error "backend contract: VKPT_SHADING is not defined"
#endif
#ifndef VKPT_VERTEX_COLORS_OF
#error "backend contract: VKPT_VERTEX_COLORS_OF is not defined"
#endif
#ifndef VKPT_UVS_OF
#error "backend contract: VKPT_UVS_OF is not defined"
#endif
#ifndef VKPT_TANGENTS_OF
#error "backend contract: VKPT_TANGENTS_OF is not defined"
#endif
#ifndef VKPT_TEXTURE_REF
#error "backend contract: VKPT_TEXTURE_REF is not defined"
#endif
#ifndef VKPT_TEXTURE
#error "backend contract: VKPT_TEXTURE is not defined"
#endif
#ifndef VKPT_TEXEL_WORD
#error "backend contract: VKPT_TEXEL_WORD is not defined"
#endif
#ifndef VKPT_TEXEL_DECODE
#error "backend contract: VKPT_TEXEL_DECODE is not defined"
#endif
#ifndef VKPT_ENV_TEXEL
#error "backend contract: VKPT_ENV_TEXEL is not defined"
#endif
#ifndef VKPT_ENV_CDF
#error "backend contract: VKPT_ENV_CDF is not defined"
#endif

#endif

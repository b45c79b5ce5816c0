// Every binding index and constant of the GPU-visible records, shared by C++ and GLSL.
// The records themselves (Triangle, Material, Light, FrameParams…) are declared once in
// gpu_records.def, from which the build generates their C++/GLSL structs with a
// static_assert of every offset ("shared/gpu_records.h", included here) and the shaders'
// fetch functions (scene_fetch.glsl). The flag bits they hold are in material_layout.h
// and texture_layout.h.
#ifndef VKPT_LAYOUT_H
#define VKPT_LAYOUT_H
#include "prelude.h"

#include "material_layout.h"     // the material's flags
#include "shared/gpu_records.h"  // the records and the material's texture slots
#include "texture_layout.h"      // the textures' modes and decode tables

VKPT_BEGIN_NAMESPACE

// Descriptor bindings of the path-tracing pipeline (set 0).
const uint kBindingParams = 0u;     // readonly buffer FrameParams (pathtrace.comp says why not uniform)
const uint kBindingTriangles = 1u;  // texel buffer of Triangle
const uint kBindingNodes = 2u;      // texel buffer of BvhNode
const uint kBindingMaterials = 3u;  // texel buffer of Material
const uint kBindingLights = 4u;     // texel buffer of Light
const uint kBindingAccum = 5u;      // buffer vec4[2 per pixel]: Σ L, Σ L²
const uint kBindingCounters = 6u;   // buffer uvec4[] per pixel: rays, non-finite, cut short, samples
// The trace-only kernel (trace.comp) reuses kBindingTriangles and kBindingNodes, plus:
const uint kBindingRays = 7u;       // readonly buffer RayQuery[]
const uint kBindingHits = 8u;       // buffer HitRecord[]
// pathtrace.comp again:
const uint kBindingLoopStats = 9u;  // buffer uint: most loop passes per sample of a SIMD group
const uint kBindingShading = 10u;   // texel buffer of TriangleShading, indexed by Triangle.sourceIndex
const uint kBindingAlbedoTables = 13u;  // texel buffer of the albedo tables (shared/albedo_tables.h)
const uint kBindingVertexColors = 14u;  // texel buffer of TriangleColors, indexed by Triangle.sourceIndex
// Textures (shared/texture.h); a 1-texel dummy of each when the scene has none.
const uint kBindingTextures = 15u;          // texel buffer of Texture
const uint kBindingTexels = 16u;            // RGBA8 texels of every texture's levels, four per RGBA32UI texel
const uint kBindingTexelDecode = 17u;       // the sRGB byte → float table (kTexelDecodeLinear floats), four per texel
const uint kBindingMaterialTextures = 18u;  // texel buffer of TextureRef, kTextureSlots per material
const uint kBindingVertexUVs = 19u;         // texel buffer of TriangleUVs, indexed by Triangle.sourceIndex
const uint kBindingTangents = 20u;          // texel buffer of TriangleTangents, indexed by Triangle.sourceIndex
// The texels past the first FrameParams::texelSplit, when one texel buffer cannot hold the
// store (its device's maxTexelBufferElements); else a 1-texel dummy.
const uint kBindingTexelsHigh = 22u;
// The triangles from FrameParams::triangleSplit on, and the texture coordinates from
// FrameParams::uvSplit on, when one texel buffer cannot hold them; else a 1-texel dummy
// (trace.comp takes the triangles' split as a push constant).
const uint kBindingTrianglesHigh = 25u;
const uint kBindingVertexUVsHigh = 26u;
// Adaptive sampling: per pixel 1 if it takes this pass's samples, else 0 (read when
// FrameParams::adaptive is 1).
const uint kBindingActive = 23u;
// aov.comp (shared/aov.h): per pixel kAovSumsPerPixel vec4 of AOV sums, read back by the
// host; it reuses the scene bindings above and kBindingParams.
const uint kBindingAovSums = 24u;
const uint kAovSumsPerPixel = 3u;
// aov.comp: per pixel one uint, AovSample::triangle of sample 0 (filled with kInvalidIndex
// before the pass).
const uint kBindingAovTriangles = 27u;

// Descriptor bindings of the denoiser (denoise.comp, shared/denoise.h), one vec4 per pixel each.
const uint kBindingDenoiseColor = 0u;   // readonly: this iteration's input (RGB, luminance variance)
const uint kBindingDenoiseGuide = 1u;   // readonly: normal, depth
const uint kBindingDenoiseAlbedo = 2u;  // readonly: albedo, 0
const uint kBindingDenoiseOut = 3u;     // this iteration's output
const uint kDenoiseIterations = 5u;     // its taps reach 2 · 2^4 = 32 pixels away

// The environment map (shared/environment.h), both as RGBA32UI texel buffers; a 1-texel
// dummy of each when there is none (FrameParams::envWidth == 0).
const uint kBindingEnvRadiance = 11u;      // W·H texels, row-major from the top row: (RGB, 0)
const uint kBindingEnvDistribution = 12u;  // W·H + H floats, 4 per texel: kEnvCdf* below

// Grid points per axis of the GGX albedo table (shared/ggx_albedo.h).
const uint kGgxAlbedoSize = 64u;
// Grid points of the rough dielectric's albedo table that follows it: of the ior (from 1
// to kGlassAlbedoMaxIor), of cos θ and of roughness.
const uint kGlassAlbedoIors = 48u;
const uint kGlassAlbedoCosines = 32u;
const uint kGlassAlbedoRoughnesses = 48u;
const float kGlassAlbedoMaxIor = 3.0f;
// Pair index of the sheen albedo table (shared/sheen.h), after the two above, and its
// grid points of cos θ and of log α.
const uint kSheenAlbedoOffset =
    kGgxAlbedoSize * (kGgxAlbedoSize + 1u) + kGlassAlbedoIors * kGlassAlbedoCosines * kGlassAlbedoRoughnesses;
const uint kSheenAlbedoCosines = 64u;
const uint kSheenAlbedoRoughnesses = 48u;
// Pair index of the hero wavelength's bins (shared/dispersion.h), after the sheen table:
// two pairs (one texel) per bin of equal probability and two after the last.
const uint kWavelengthOffset = kSheenAlbedoOffset + kSheenAlbedoCosines * (kSheenAlbedoRoughnesses - 1u);
const uint kWavelengthBins = 256u;

// lavapipe ends a shader once its SIMD group has run 65535 loop passes in total
// (traverse.glsl); pathtrace.comp keeps clear of it by a margin for the small loops not
// counted exactly, and the host sizes its runs of samples to fit.
const uint kLoopBudget = 65535u - 256u;

const uint kInvalidIndex = 0xFFFFFFFFu;

const uint kMaxLeafSize = 15u;  // triangles in a BVH leaf (BvhNode::leaf)

const uint kShadingHasNormals = 1u;  // TriangleShading::flags: the triangle has vertex normals

const uint kTangentsMissing = 8u;  // TriangleTangents::signs: some vertex has no tangent

// Light types (shared/lights.h).
const uint kLightTriangle = 0u;          // emits from its front face
const uint kLightTwoSidedTriangle = 1u;  // emits from both faces (double-sided material)
const uint kLightPoint = 2u;
const uint kLightSpot = 3u;
const uint kLightDirectional = 4u;
const uint kLightEnvironment = 5u;  // the environment map (shared/environment.h)

const uint kLightNodeTwoSided = 0x80000000u;  // LightTreeNode::split: some light emits both ways

// The environment map's sampling distribution is one float array: the conditional CDF of
// row r (inclusive running sums, the last exactly 1) at [r·W, r·W + W), then the marginal
// CDF over the rows at [W·H, W·H + H). Four floats per texel on the GPU.
const uint kEnvCdfsPerTexel = 4u;

VKPT_END_NAMESPACE

#endif

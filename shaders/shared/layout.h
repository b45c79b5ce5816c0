// Every GPU-visible struct and binding index, shared by C++ and GLSL (the BVH's in
// bvh_layout.h, the material's in material_layout.h, the textures' in texture_layout.h).
//
// All structs follow std430 rules and are built only from 4-byte scalars and
// (vec3, 4-byte scalar) pairs, so the C++ layout (glm::vec3 = 12 bytes, align 4)
// equals the GLSL one (vec3 aligned to 16). Never put a vec3 after a vec3: GLSL
// would insert 4 bytes of padding that C++ does not. host/render/gpu_layout.cpp
// static_asserts every size and offset below.
#ifndef VKPT_LAYOUT_H
#define VKPT_LAYOUT_H
#include "prelude.h"

#include "bvh_layout.h"       // the BVH nodes
#include "material_layout.h"  // the material
#include "texture_layout.h"   // the textures' structs and the material's texture slots

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

// A triangle in leaf order, stored as v0 and two edges: exactly what the
// Möller–Trumbore test consumes, so the hot loop loads 36 bytes and computes nothing
// it could have precomputed.
struct Triangle {
  vec3 v0;
  uint material;
  vec3 e1;  // v1 - v0
  uint sourceIndex;  // index of the triangle in the Scene (before BVH reordering)
  vec3 e2;  // v2 - v0
  uint light;  // its entry in the Light table if it emits, else kInvalidIndex (for MIS)
};

const uint kShadingHasNormals = 1u;

// Per scene triangle (indexed by Triangle::sourceIndex, so spatial-split copies share it):
// vertex normals as octahedral unit vectors, two snorm16 each (Cigolle et al. 2014).
struct TriangleShading {
  uint n0;
  uint n1;
  uint n2;
  uint flags;  // kShadingHasNormals; without it n0..n2 are 0 and the triangle is flat
};

// Per scene triangle (indexed by Triangle::sourceIndex, like TriangleShading): glTF
// COLOR_0 of its three vertices, linear RGBA as unorm16 (exact for unorm8 and unorm16
// files), vertex k's (R, G) in rgK and (B, A) in baK (packUnorm2x16: R, B in the low
// bits). Present only when some triangle of the scene has COLOR_0; the others are white.
struct TriangleColors {
  uint rg0;
  uint ba0;
  uint rg1;
  uint ba1;
  uint rg2;
  uint ba2;
  uint pad0;
  uint pad1;
};

// Per scene triangle (indexed by Triangle::sourceIndex): glTF TEXCOORD_0 and TEXCOORD_1
// of its three vertices (0 where the primitive has no such set). Present only when some
// material has a texture.
struct TriangleUVs {
  vec2 uv00;  // uvSV: set S of vertex V
  vec2 uv01;
  vec2 uv02;
  vec2 uv10;
  vec2 uv11;
  vec2 uv12;
};

// Per scene triangle (indexed by Triangle::sourceIndex): glTF TANGENT of its three
// vertices in world space, octahedrally encoded like TriangleShading's normals, and in
// bit k of `signs` whether vertex k's bitangent sign (TANGENT.w) is −1; kTangentsMissing
// where some vertex has none. Present only when some material has a normal texture.
struct TriangleTangents {
  uint t0;
  uint t1;
  uint t2;
  uint signs;
};
const uint kTangentsMissing = 8u;

// Light types (shared/lights.h).
const uint kLightTriangle = 0u;          // emits from its front face
const uint kLightTwoSidedTriangle = 1u;  // emits from both faces (double-sided material)
const uint kLightPoint = 2u;
const uint kLightSpot = 3u;
const uint kLightDirectional = 4u;
const uint kLightEnvironment = 5u;  // the environment map (shared/environment.h)

// One light of the light-sampling distribution (next-event estimation). Lights are chosen
// with probability pmf ∝ estimated power; cdf is the inclusive running sum (the last one
// is exactly 1).
struct Light {
  vec3 position;   // point, spot: where it is
  uint triangle;   // triangles: index into the leaf-ordered Triangle array
  vec3 direction;  // spot, directional: unit, the way light travels; triangles: unit front normal
  uint type;       // kLight*
  vec3 radiance;   // triangles: Le; point, spot: intensity I; directional: irradiance E
  float extent;    // triangles: area; point, spot: range (0: unlimited)
  float cdf;
  float pmf;
  float cosOuter;  // spot: cosines of the outer and inner cone angles
  float cosInner;
};

// A node of the light tree (shared/light_tree.h, host/render/light_tree.h): the bounds of
// the finite lights [first, end) of the light table, depth first, a node's left child
// right after it. Its right child holds lights [split, end) and lies 2 (split − first)
// nodes after it (a subtree over c lights has 2c − 1 nodes); a node of one light is a leaf.
struct LightTreeNode {
  vec3 center;  // of a sphere holding every light's points
  float radius;
  vec3 axis;        // unit: the axis of the cone of the lights' normals (or spot directions)
  float intensity;  // Σ over the lights of their greatest radiant intensity (luminance)
  float cosThetaO;  // the cone's half-angle θo: every normal is within θo of the axis
  float sinThetaO;
  float cosThetaE;  // θe: how far beyond its normal a light emits (π/2 for a triangle)
  uint split;       // bits 0–30: the right child's first light; bit 31: a light emits both ways
};
const uint kLightNodeTwoSided = 0x80000000u;

// The shaders read the scene arrays above as RGBA32UI texels (shaders/scene_fetch.glsl):
// 16 bytes each, so a struct's texel t holds its bytes [16t, 16t + 16).
const uint kTexelsPerTriangle = 3u;
const uint kTexelsPerWideNode = 4u;
const uint kTexelsPerMaterial = 10u;
const uint kTexelsPerLight = 4u;
const uint kTexelsPerLightNode = 3u;  // after the lights, in the same texel buffer
const uint kTexelsPerShading = 1u;
const uint kTexelsPerColors = 2u;
const uint kTexelsPerUVs = 3u;
const uint kTexelsPerTangents = 1u;
const uint kTexelsPerTextureRef = 2u;

// The environment map's sampling distribution is one float array: the conditional CDF of
// row r (inclusive running sums, the last exactly 1) at [r·W, r·W + W), then the marginal
// CDF over the rows at [W·H, W·H + H). Four floats per texel on the GPU.
const uint kEnvCdfsPerTexel = 4u;

// A ray for the trace-only kernel: closest hit along origin + t·dir, t ∈ (0, tMax).
struct RayQuery {
  vec3 origin;
  float tMax;
  vec3 dir;
  uint pad0;
};

// Closest hit: t < 0 for none; (b1, b2) barycentrics; triangle in leaf order.
struct HitRecord {
  float t;
  float b1;
  float b2;
  uint triangle;
};

// Per-render constants. The camera ray through film point (sx, sy) ∈ [-1,1]² has the
// direction forward + sx * tanHalfFovY * aspect * right + sy * tanHalfFovY * up
// (see GenerateCameraRay in estimator.h).
struct FrameParams {
  vec3 origin;
  float tanHalfFovY;
  vec3 right;
  float aspect;
  vec3 up;
  uint width;
  vec3 forward;
  uint height;
  uint seed;
  uint sampleBegin;  // first sample index of this dispatch
  uint sampleCount;  // samples per pixel in this dispatch
  uint maxDepth;
  uint rrDepth;
  uint lightCount;
  uint nodeCount;     // WideBvhNodes per copy
  uint pad0;          // places background on the 16-byte boundary std430 gives a vec3
  vec3 background;    // radiance arriving from every direction no triangle blocks
  uint orthographic;  // 1: parallel rays; tanHalfFovY then holds the half view height
  uint nodeCopies;    // 1, or 8 direction-ordered copies of the BVH (bvh/quantized_layout.h)
  uint tileRowStride; // GPU: workgroup row y renders tile row (y * stride) mod rows
  uint envLight;      // the environment map's entry in the light table, or kInvalidIndex
  uint textureLod;    // 1: mip levels chosen by ray cones (shared/ray_cone.h); 0: level 0 everywhere
  // The environment map (shared/environment.h): envWidth == 0 means none, and rays that
  // leave the scene see `background` instead.
  uint envWidth;
  uint envHeight;
  float envIntensity;    // radiance scale (--env-intensity)
  float envRotationCos;  // the map turned by α about +Y (--env-rotation): cos α, sin α
  float envRotationSin;
  uint texelSplit;     // RGBA32UI texels of the store in kBindingTexels; the rest are in kBindingTexelsHigh
  uint adaptive;       // 1: only the pixels kBindingActive marks take samples
  uint triangleSplit;  // Triangles in kBindingTriangles; the rest are in kBindingTrianglesHigh
  uint uvSplit;        // TriangleUVs in kBindingVertexUVs; the rest are in kBindingVertexUVsHigh
  uint treeLights;     // lights [0, treeLights) are chosen through the light tree; 0: no tree
  uint treeDepth;      // the light tree's depth (a leaf under the root: 1)
  uint pad8;           // std430 rounds the struct up to its vec3's alignment, 16 bytes
};

VKPT_END_NAMESPACE

#endif

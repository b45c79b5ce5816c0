// Compile-time proof that the C++ view of every GPU struct in shaders/shared/layout.h
// has the std430 layout the shaders read. A failing assert here means a struct was
// edited in a way GLSL would pad differently.
#include <cstddef>

#include "shared/layout.h"

namespace vkpt::shader {

static_assert(sizeof(vec3) == 12 && alignof(vec3) == 4, "glm::vec3 must be 3 packed floats");

static_assert(sizeof(Triangle) == 48);
static_assert(offsetof(Triangle, v0) == 0 && offsetof(Triangle, material) == 12);
static_assert(offsetof(Triangle, e1) == 16 && offsetof(Triangle, sourceIndex) == 28);
static_assert(offsetof(Triangle, e2) == 32 && offsetof(Triangle, light) == 44);

static_assert(sizeof(BvhNode) == 32);
static_assert(offsetof(BvhNode, lo) == 0 && offsetof(BvhNode, skip) == 12);
static_assert(offsetof(BvhNode, hi) == 16 && offsetof(BvhNode, leaf) == 28);
static_assert(sizeof(WideBvhNode) == 64 && offsetof(WideBvhNode, exponents) == 12);
static_assert(offsetof(WideBvhNode, lo) == 16 && offsetof(WideBvhNode, hi) == 32 && offsetof(WideBvhNode, child) == 48);

static_assert(sizeof(Material) == 160);
static_assert(offsetof(Material, baseColor) == 0 && offsetof(Material, metallic) == 12);
static_assert(offsetof(Material, emission) == 16 && offsetof(Material, roughness) == 28);
static_assert(offsetof(Material, specularColor) == 32 && offsetof(Material, specular) == 44);
static_assert(offsetof(Material, attenuation) == 48 && offsetof(Material, ior) == 60);
static_assert(offsetof(Material, transmission) == 64 && offsetof(Material, flags) == 68);
static_assert(offsetof(Material, normalScale) == 72 && offsetof(Material, alpha) == 76);
static_assert(offsetof(Material, alphaCutoff) == 80);
static_assert(offsetof(Material, clearcoatNormalScale) == 92 && offsetof(Material, sheenColor) == 96);
static_assert(offsetof(Material, sheenRoughness) == 108 && offsetof(Material, diffuseTransmissionColor) == 112);
static_assert(offsetof(Material, diffuseTransmission) == 124 && offsetof(Material, iridescence) == 128);
static_assert(offsetof(Material, iridescenceThicknessMin) == 136 && offsetof(Material, iridescenceThickness) == 140);
static_assert(offsetof(Material, anisotropy) == 144 && offsetof(Material, anisotropyDirection) == 152);

static_assert(sizeof(Light) == 64);
static_assert(offsetof(Light, position) == 0 && offsetof(Light, triangle) == 12);
static_assert(offsetof(Light, direction) == 16 && offsetof(Light, type) == 28);
static_assert(offsetof(Light, radiance) == 32 && offsetof(Light, extent) == 44);
static_assert(offsetof(Light, cdf) == 48 && offsetof(Light, cosInner) == 60);
static_assert(sizeof(LightTreeNode) == 16 * kTexelsPerLightNode);
static_assert(offsetof(LightTreeNode, radius) == 12 && offsetof(LightTreeNode, axis) == 16);
static_assert(offsetof(LightTreeNode, intensity) == 28 && offsetof(LightTreeNode, split) == 44);

static_assert(sizeof(TriangleShading) == 16 * kTexelsPerShading);
static_assert(offsetof(TriangleShading, n1) == 4 && offsetof(TriangleShading, n2) == 8);
static_assert(offsetof(TriangleShading, flags) == 12);

static_assert(sizeof(TriangleColors) == 16 * kTexelsPerColors);
static_assert(offsetof(TriangleColors, rg1) == 8 && offsetof(TriangleColors, ba2) == 20);

static_assert(sizeof(vec2) == 8 && sizeof(TriangleUVs) == 16 * kTexelsPerUVs);
static_assert(offsetof(TriangleUVs, uv02) == 16 && offsetof(TriangleUVs, uv10) == 24);
static_assert(sizeof(TriangleTangents) == 16 * kTexelsPerTangents && offsetof(TriangleTangents, signs) == 12);
static_assert(sizeof(Texture) == 16 && offsetof(Texture, mode) == 12);
static_assert(sizeof(TextureRef) == 16 * kTexelsPerTextureRef);
static_assert(offsetof(TextureRef, m00) == 8 && offsetof(TextureRef, m12) == 28);

static_assert(sizeof(RayQuery) == 32);
static_assert(sizeof(Triangle) == 16 * kTexelsPerTriangle && sizeof(WideBvhNode) == 16 * kTexelsPerWideNode);
static_assert(sizeof(Material) == 16 * kTexelsPerMaterial && sizeof(Light) == 16 * kTexelsPerLight);

static_assert(offsetof(RayQuery, tMax) == 12 && offsetof(RayQuery, dir) == 16);
static_assert(sizeof(HitRecord) == 16 && offsetof(HitRecord, triangle) == 12);

static_assert(sizeof(FrameParams) == 176);
static_assert(offsetof(FrameParams, origin) == 0 && offsetof(FrameParams, tanHalfFovY) == 12);
static_assert(offsetof(FrameParams, right) == 16 && offsetof(FrameParams, aspect) == 28);
static_assert(offsetof(FrameParams, up) == 32 && offsetof(FrameParams, width) == 44);
static_assert(offsetof(FrameParams, forward) == 48 && offsetof(FrameParams, height) == 60);
static_assert(offsetof(FrameParams, seed) == 64 && offsetof(FrameParams, pad0) == 92);
static_assert(offsetof(FrameParams, background) == 96 && offsetof(FrameParams, orthographic) == 108);
static_assert(offsetof(FrameParams, nodeCopies) == 112);
static_assert(offsetof(FrameParams, envWidth) == 128 && offsetof(FrameParams, envHeight) == 132);
static_assert(offsetof(FrameParams, envIntensity) == 136 && offsetof(FrameParams, envRotationSin) == 144);
static_assert(offsetof(FrameParams, triangleSplit) == 156 && offsetof(FrameParams, uvSplit) == 160);

}  // namespace vkpt::shader

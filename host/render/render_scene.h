// What a renderer consumes: the Scene's triangles in BVH leaf order as shader::Triangle,
// the BVH in three layouts (the builder's flattened tree, eight-wide nodes for the CPU,
// four-wide quantised nodes for the GPU),
// materials, the light table for light sampling, per-triangle shading normals, vertex
// colours and texture coordinates, and the textures. The
// shader-layout vectors are uploaded verbatim by the Vulkan backend; the CPU reference
// reads them directly.
#pragma once

#include <vector>

#include "bvh/bvh.h"
#include "bvh/wide_layout.h"
#include "render/environment_map.h"
#include "scene/scene.h"
#include "shared/layout.h"

namespace vkpt::internal {

struct RenderScene {
  std::vector<shader::Triangle> triangles;  // BVH leaf order
  HugeVector<shader::BvhNode> nodes;        // the flattened tree, bvhStats.nodes nodes (see Bvh)
  uint32_t nodeCopies = 1;                  // of gpuNodes: 8 direction-ordered ones, or 1
  BvhWideLayout wideLayout;                 // from `nodes`, for the CPU tracer (if asked for)
  // From `nodes`, nodeCopies copies for the GPU (bvh/quantized_layout.h).
  std::vector<shader::WideBvhNode> gpuNodes;
  std::vector<shader::Material> materials;
  std::vector<shader::Light> lights;  // empty: the scene is dark (render/light_table.h)
  // Over lights [0, treeLights) when the scene chooses its finite lights by a tree
  // (render/light_tree.h); else empty and treeLights 0.
  std::vector<shader::LightTreeNode> lightTree;
  uint32_t treeLights = 0;
  uint32_t lightTreeDepth = 0;
  // One per Scene triangle, degenerate ones included, so that Triangle::sourceIndex
  // indexes it directly (and spatial-split copies of a triangle share it).
  std::vector<shader::TriangleShading> shading;
  // Indexed like `shading`; empty when no triangle has vertex colours.
  std::vector<shader::TriangleColors> vertexColors;
  // Textures (shared/texture.h, material_textures.h); all empty when no material has one.
  std::vector<shader::TriangleTangents> tangents;  // indexed like `shading`; empty without normal maps
  std::vector<shader::TriangleUVs> uvs;            // indexed like `shading`
  std::vector<shader::TextureRef> textureRefs;     // kTextureSlots per material
  std::vector<shader::Texture> textures;
  std::vector<uint32_t> texels;    // TextureStore::words
  std::vector<float> texelDecode;  // TexelDecodeTable()
  bool alphaTested = false;        // some triangle's material is alpha MASK or BLEND (shared/alpha.h)
  BvhStats bvhStats;
  uint32_t degenerateTriangles = 0;  // dropped: zero area (see IsDegenerate)
  double totalEmittedPower = 0.0;    // Σ of the lights' power estimates
  std::vector<double> lightPower;    // per light, what its pmf is proportional to
  double sceneRadius = 0.0;          // of the scene's bounding sphere (directional lights' power)
  EnvironmentMap environment;        // none unless the caller sets one (--env)
};

// A triangle whose edges are parallel to float precision has no area to hit or emit
// from, but a ray test on it can report a spurious hit far from its vertices; such
// triangles are left out of the RenderScene.
bool IsDegenerate(const SceneTriangle& t);

// Whether some triangle's material is not Lambertian (shared/bsdf.h's IsLambertian).
// Materials no triangle uses do not count: the loader always appends glTF's default
// material, a metal, whether or not a primitive needs it.
bool UsesGlossyMaterial(const RenderScene& scene);
// Likewise, whether some triangle's material bounds a volume (kMaterialVolume).
bool UsesVolumeMaterial(const RenderScene& scene);
// And whether some triangle's material has a clear coat (KHR_materials_clearcoat).
bool UsesClearcoat(const RenderScene& scene);
// And whether some triangle's material has a sheen (KHR_materials_sheen).
bool UsesSheen(const RenderScene& scene);
// And whether some triangle's material transmits diffusely (KHR_materials_diffuse_transmission).
bool UsesDiffuseTransmission(const RenderScene& scene);
// And whether some triangle's material is iridescent (KHR_materials_iridescence).
bool UsesIridescence(const RenderScene& scene);
// And whether some triangle's material is anisotropic (KHR_materials_anisotropy).
bool UsesAnisotropy(const RenderScene& scene);
// And whether some triangle's material is dispersive (KHR_materials_dispersion).
bool UsesDispersion(const RenderScene& scene);

// Whether the scene has lights meant to light it: punctual lights, or emissive triangles
// whose emission is not painted by an emissive texture (a texture paints screens, dials
// and glowing trim: DamagedHelmet's 15,452 triangles all "emit" that way, yet show
// nothing without a light). The environment's entry is none: it lights from outside.
bool HasLightSources(const RenderScene& scene);

// `forCpu`: lay the tree out for the CPU tracer (wideLayout); `forGpu`: for the shader
// (gpuNodes). A render on one backend skips the other's: on a large scene it costs time
// and memory that nothing would read.
RenderScene PrepareRenderScene(const Scene& scene, const BvhBuildOptions& options = {}, bool forCpu = true,
                               bool forGpu = true);

// rs's materials and light table made again from `scene`, whose materials or punctual
// lights changed but whose triangles did not, as PrepareRenderScene makes them. The caller
// adds the environment and chooses the light sampler again, as after PrepareRenderScene.
void RestyleRenderScene(const Scene& scene, RenderScene& rs);

// Each triangle's index in the light table (shader::kInvalidIndex: it emits nothing), in
// leaf order.
std::vector<uint32_t> TriangleLights(const RenderScene& rs);

// The frame constants for a scene, camera and image size; seed, sample range, depths and
// background are left 0 for the caller, the environment map unturned at intensity 1,
// mip levels chosen by ray cones.
shader::FrameParams MakeFrameParams(const RenderScene& scene, const Camera& camera, uint32_t width, uint32_t height);

}  // namespace vkpt::internal

// The Vulkan backend: the scene uploaded once into device-local buffers read as texel
// buffers, then pathtrace.comp dispatched in batches of samples per pixel into per-pixel
// sums (storage buffers), which are read back and resolved by a Film (render/film.h).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "render/film.h"
#include "render/render_scene.h"
#include "vk/buffer.h"
#include "vk/compute_pipeline.h"
#include "vk/context.h"

namespace vkpt::internal::vk {

struct GpuRenderOptions {
  // Samples per pixel per submission (in dispatches of samplesPerInvocation each); 0
  // picks about 2^20 paths per submission, short enough that a desktop GPU's watchdog
  // never fires.
  uint32_t batch = 0;
  // Samples each invocation computes in one dispatch (path regeneration, pathtrace.comp);
  // 0 sizes the run from the loop passes per sample measured so far (RunLength). The image
  // is the same for every choice.
  uint32_t samplesPerInvocation = 0;
  std::function<void(double)> progress;  // finished fraction, after every batch
};

// What a renderer derived from GpuRenderer may substitute, through its protected
// constructor: kernels with the interface of pathtrace.comp and trace.comp (bindings,
// push and specialization constants), and a cap on the texels per buffer below the
// device's limit, so that the arrays that may take two buffers (triangles, texture
// coordinates, the texel store) take two on any device. The product renders with none of
// these; tests derive a renderer to run deliberately wrong kernels and probes, and to
// split small scenes.
struct GpuRendererOverrides {
  std::span<const uint32_t> pathTraceSpirv = {};  // empty: the embedded pathtrace.comp
  std::span<const uint32_t> traceSpirv = {};      // empty: the embedded trace.comp
  uint32_t maxTexelsPerBuffer = 0;                // 0: the device's limit
};

class GpuRenderer {
 public:
  // Uploads the scene.
  GpuRenderer(const Context& ctx, const RenderScene& scene) : GpuRenderer(ctx, scene, GpuRendererOverrides{}) {}
  // A render in progress (params.sampleBegin and sampleCount are ignored: each pass
  // names its samples); it must not outlive this renderer. options.progress is unused:
  // each pass takes its own.
  std::unique_ptr<FrameRenderer> BeginFrame(const shader::FrameParams& params, const GpuRenderOptions& options = {});
  // Samples [params.sampleBegin, params.sampleBegin + params.sampleCount) of every pixel
  // in one pass of a BeginFrame render.
  RenderResult Render(const shader::FrameParams& params, const GpuRenderOptions& options = {});

  // Closest hits of a batch of rays with the shader's traversal (trace.comp). `seconds`,
  // if given, receives the time of the dispatch alone (no upload, pipeline creation or
  // readback), for benchmarks.
  std::vector<shader::HitRecord> Trace(const std::vector<shader::RayQuery>& rays, double* seconds = nullptr);

  // Uploads `scene`'s materials and light table again, and its triangles where
  // `triangleLights` (their light indices changed), after RestyleRenderScene (the BVH,
  // shading and textures are as they were). No frame may be begun.
  void Restyle(const RenderScene& scene, bool triangleLights);

 protected:
  GpuRenderer(const Context& ctx, const RenderScene& scene, const GpuRendererOverrides& overrides);

 private:
  // The scene's texel buffers as bound by every kernel that reads the scene, and the
  // specialization constants of scene_constants.glsl for `frame`.
  std::vector<BufferBinding> SceneBindings() const;
  std::vector<uint32_t> Specialization(const shader::FrameParams& frame) const;
  // The specialization constants' account of `scene`'s materials and lights.
  void ReadMaterials(const RenderScene& scene);

  const Context& ctx_;
  std::span<const uint32_t> pathTraceSpirv_, traceSpirv_;
  // The scene is read as texel buffers (shaders/scene_fetch.glsl says why).
  SplitTexelBuffer triangles_;  // in two buffers if one cannot hold them
  TexelBuffer nodes_, materials_, lights_, albedoTables_, shading_;
  // The vertex colours; without any, one zero texel that the shader never reads.
  TexelBuffer vertexColors_;
  // Texture coordinates and textures (shared/texture.h); one zero texel each without.
  SplitTexelBuffer uvs_;  // in two buffers if one cannot hold them
  TexelBuffer tangents_, textureRefs_, textures_;
  SplitTexelBuffer texels_;  // the texel store, in two buffers if one cannot hold it
  TexelBuffer texelDecode_;
  // The environment map's texels and CDFs; without a map one zero texel each, so that the
  // descriptor set is complete all the same.
  TexelBuffer envRadiance_, envDistribution_;
  // What the scene has, for pathtrace.comp's specialization constants 0-18 (the frame
  // tells whether lights are sampled at all and whether there is an environment map).
  // Of its geometry:
  bool hasSmoothNormals_;  // some triangle has vertex normals
  bool hasVertexColors_;   // some triangle has COLOR_0
  bool hasTextures_;       // some material has a texture
  bool hasNormalMaps_;     // some material has a normal texture
  // Of its materials and lights (ReadMaterials):
  uint32_t lightTypes_ = 0;              // bit 1 << type for each type in the light table
  bool hasGlossy_ = false;               // some triangle's material is not Lambertian
  bool hasVolumes_ = false;              // some triangle's material bounds a volume
  bool hasClearcoat_ = false;            // some triangle's material has a clear coat
  bool hasSheen_ = false;                // some triangle's material has a sheen
  bool hasDiffuseTransmission_ = false;  // some triangle's material transmits diffusely
  bool hasIridescence_ = false;          // some triangle's material is iridescent
  bool hasAnisotropy_ = false;           // some triangle's material is anisotropic
  bool hasDispersion_ = false;           // some triangle's material is dispersive
  bool hasAlpha_ = false;                // some triangle's material is alpha MASK or BLEND
  bool hasExtensionTextures_ = false;    // some material has a texture of a material extension
  // The device runs both sides of every branch, masked (a CPU device such as lavapipe):
  // constant 19, shared/texture.h's VKPT_MASKED_BRANCHES.
  bool masksBranches_;
  uint32_t nodeCount_, nodeCopies_;  // for trace.comp (pathtrace.comp reads FrameParams)
  uint32_t maxTexelsPerBuffer_;      // GpuRendererOverrides's
};

}  // namespace vkpt::internal::vk

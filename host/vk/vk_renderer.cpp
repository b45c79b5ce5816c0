#include "vk/vk_renderer.h"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstring>
#include <memory>
#include <span>
#include <string>

#include "kPathTraceSpirv.h"
#include "kTraceSpirv.h"
#include "shared/bsdf.h"
#include "util/byte_size.h"
#include "util/error.h"
#include "vk/compute_pipeline.h"
#include "vk/gpu_frame.h"
#include "vk/vk_check.h"

namespace vkpt::internal::vk {
namespace {

template <class T>
Buffer Upload(const Context& ctx, const std::vector<T>& v, const char* what) {
  return UploadStorage(ctx, v.data(), v.size() * sizeof(T), what);
}

template <class T>
TexelBuffer UploadArray(const Context& ctx, std::span<const T> v, const char* what) {
  return UploadTexelBuffer(ctx, v.data(), v.size() * sizeof(T), what);
}

// The light table with the light tree's nodes after it (scene_fetch.glsl's FetchLightNode).
TexelBuffer UploadLights(const Context& ctx, const RenderScene& scene) {
  const size_t lightBytes = scene.lights.size() * sizeof(shader::Light);
  std::vector<std::byte> bytes(lightBytes + scene.lightTree.size() * sizeof(shader::LightTreeNode));
  if (!scene.lights.empty()) std::memcpy(bytes.data(), scene.lights.data(), lightBytes);
  if (!scene.lightTree.empty())
    std::memcpy(bytes.data() + lightBytes, scene.lightTree.data(), bytes.size() - lightBytes);
  return UploadTexelBuffer(ctx, bytes.data(), bytes.size(), "lights");
}

// An array of whole-texel structs, in two texel buffers if one cannot hold it.
template <class T>
SplitTexelBuffer UploadSplitArray(const Context& ctx, std::span<const T> v, const char* what,
                                  uint32_t maxTexelsPerBuffer) {
  static_assert(sizeof(T) % 16 == 0);
  return UploadSplitTexelBuffer(ctx, v.data(), v.size() * sizeof(T), sizeof(T) / 16, what, maxTexelsPerBuffer);
}

}  // namespace

GpuRenderer::GpuRenderer(const Context& ctx, const RenderScene& scene, const GpuRendererOverrides& overrides)
    : ctx_(ctx),
      pathTraceSpirv_(overrides.pathTraceSpirv.empty() ? std::span<const uint32_t>(kPathTraceSpirv)
                                                       : overrides.pathTraceSpirv),
      traceSpirv_(overrides.traceSpirv.empty() ? std::span<const uint32_t>(kTraceSpirv) : overrides.traceSpirv),
      triangles_(UploadSplitArray<shader::Triangle>(ctx, scene.triangles, "triangles", overrides.maxTexelsPerBuffer)),
      nodes_(UploadArray<shader::WideBvhNode>(ctx, scene.gpuNodes, "BVH nodes")),
      materials_(UploadArray<shader::Material>(ctx, scene.materials, "materials")),
      lights_(UploadLights(ctx, scene)),
      albedoTables_(UploadArray<float>(ctx, shader::kAlbedoTables, "albedo tables")),
      shading_(UploadArray<shader::TriangleShading>(ctx, scene.shading, "shading normals")),
      vertexColors_(UploadArray<shader::TriangleColors>(ctx, scene.vertexColors, "vertex colours")),
      uvs_(UploadSplitArray<shader::TriangleUVs>(ctx, scene.uvs, "texture coordinates", overrides.maxTexelsPerBuffer)),
      tangents_(UploadArray<shader::TriangleTangents>(ctx, scene.tangents, "tangents")),
      textureRefs_(UploadArray<shader::TextureRef>(ctx, scene.textureRefs, "material textures")),
      textures_(UploadArray<shader::Texture>(ctx, scene.textures, "texture table")),
      texels_(UploadSplitTexelBuffer(ctx, scene.texels.data(), scene.texels.size() * sizeof(uint32_t), 1,
                                     "texture texels", overrides.maxTexelsPerBuffer)),
      // The sRGB table alone (none without textures): the shader computes linear bytes.
      texelDecode_(UploadArray<float>(
          ctx,
          std::span(scene.texelDecode).first(std::min<size_t>(scene.texelDecode.size(), shader::kTexelDecodeLinear)),
          "sRGB decode table")),
      envRadiance_(UploadArray<glm::vec4>(ctx, scene.environment.texels, "environment map texels")),
      envDistribution_(UploadArray<float>(ctx, scene.environment.cdf, "environment map CDFs")),
      hasSmoothNormals_(
          std::any_of(scene.shading.begin(), scene.shading.end(),
                      [](const shader::TriangleShading& s) { return (s.flags & shader::kShadingHasNormals) != 0; })),
      hasVertexColors_(!scene.vertexColors.empty()),
      hasTextures_(!scene.textureRefs.empty()),
      hasNormalMaps_(!scene.tangents.empty()),
      masksBranches_(ctx.Properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU),
      nodeCount_(uint32_t(scene.gpuNodes.size() / scene.nodeCopies)),
      nodeCopies_(scene.nodeCopies),
      maxTexelsPerBuffer_(overrides.maxTexelsPerBuffer) {
  ReadMaterials(scene);
}

void GpuRenderer::ReadMaterials(const RenderScene& scene) {
  hasGlossy_ = UsesGlossyMaterial(scene);
  hasVolumes_ = UsesVolumeMaterial(scene);
  hasClearcoat_ = UsesClearcoat(scene);
  hasSheen_ = UsesSheen(scene);
  hasDiffuseTransmission_ = UsesDiffuseTransmission(scene);
  hasIridescence_ = UsesIridescence(scene);
  hasAnisotropy_ = UsesAnisotropy(scene);
  hasDispersion_ = UsesDispersion(scene);
  hasAlpha_ = scene.alphaTested;
  hasExtensionTextures_ = std::any_of(scene.materials.begin(), scene.materials.end(), [](const shader::Material& m) {
    return (m.flags & shader::kMaterialExtensionTextured) != 0u;
  });
  lightTypes_ = 0;
  for (const shader::Light& l : scene.lights) lightTypes_ |= 1u << l.type;
}

void GpuRenderer::Restyle(const RenderScene& scene, bool triangleLights) {
  // Each buffer is released as its replacement is assigned: one array at a time is held twice.
  if (triangleLights)
    triangles_ = UploadSplitArray<shader::Triangle>(ctx_, scene.triangles, "triangles", maxTexelsPerBuffer_);
  materials_ = UploadArray<shader::Material>(ctx_, scene.materials, "materials");
  lights_ = UploadLights(ctx_, scene);
  ReadMaterials(scene);
}

std::vector<BufferBinding> GpuRenderer::SceneBindings() const {
  return {TexelBinding(shader::kBindingTriangles, triangles_.low),
          TexelBinding(shader::kBindingTrianglesHigh, triangles_.high),
          TexelBinding(shader::kBindingNodes, nodes_),
          TexelBinding(shader::kBindingMaterials, materials_),
          TexelBinding(shader::kBindingLights, lights_),
          TexelBinding(shader::kBindingAlbedoTables, albedoTables_),
          TexelBinding(shader::kBindingShading, shading_),
          TexelBinding(shader::kBindingVertexColors, vertexColors_),
          TexelBinding(shader::kBindingVertexUVs, uvs_.low),
          TexelBinding(shader::kBindingVertexUVsHigh, uvs_.high),
          TexelBinding(shader::kBindingTangents, tangents_),
          TexelBinding(shader::kBindingMaterialTextures, textureRefs_),
          TexelBinding(shader::kBindingTextures, textures_),
          TexelBinding(shader::kBindingTexels, texels_.low),
          TexelBinding(shader::kBindingTexelsHigh, texels_.high),
          TexelBinding(shader::kBindingTexelDecode, texelDecode_),
          TexelBinding(shader::kBindingEnvRadiance, envRadiance_),
          TexelBinding(shader::kBindingEnvDistribution, envDistribution_)};
}

std::vector<uint32_t> GpuRenderer::Specialization(const shader::FrameParams& frame) const {
  return {frame.lightCount > 0 ? lightTypes_ : 0u,
          hasGlossy_ ? 1u : 0u,
          hasSmoothNormals_ ? 1u : 0u,
          frame.envWidth > 0 ? 1u : 0u,
          hasVertexColors_ ? 1u : 0u,
          hasVolumes_ ? 1u : 0u,
          hasTextures_ ? 1u : 0u,
          hasNormalMaps_ ? 1u : 0u,
          hasAlpha_ ? 1u : 0u,
          hasExtensionTextures_ ? 1u : 0u,
          texels_.twoBuffers ? 1u : 0u,
          triangles_.twoBuffers ? 1u : 0u,
          uvs_.twoBuffers ? 1u : 0u,
          hasClearcoat_ ? 1u : 0u,
          hasSheen_ ? 1u : 0u,
          hasDiffuseTransmission_ ? 1u : 0u,
          hasIridescence_ ? 1u : 0u,
          hasAnisotropy_ ? 1u : 0u,
          hasDispersion_ ? 1u : 0u,
          masksBranches_ ? 1u : 0u,
          frame.treeLights > 0 ? 1u : 0u};
}

std::unique_ptr<FrameRenderer> GpuRenderer::BeginFrame(const shader::FrameParams& frame,
                                                       const GpuRenderOptions& options) {
  FrameBuffers b = MakeFrameBuffers(ctx_, uint64_t(frame.width) * frame.height);
  shader::FrameParams p = frame;
  p.texelSplit = texels_.split;
  p.triangleSplit = triangles_.split;
  p.uvSplit = uvs_.split;
  KernelFactory kernels = [this, p](const uint32_t* spirv, size_t spirvBytes, std::vector<BufferBinding> bindings,
                                    const char* name, uint32_t pushConstantBytes) {
    std::vector<BufferBinding> scene = SceneBindings();
    bindings.insert(bindings.end(), scene.begin(), scene.end());
    return std::make_unique<ComputePipeline>(ctx_, spirv, spirvBytes, bindings, name, pushConstantBytes,
                                             Specialization(p));
  };
  auto pipeline = kernels(pathTraceSpirv_.data(), pathTraceSpirv_.size_bytes(),
                          {FrameParamsBinding(b),
                           {shader::kBindingAccum, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, b.accum.Handle()},
                           {shader::kBindingCounters, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, b.counters.Handle()},
                           {shader::kBindingActive, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, b.active.Handle()},
                           {shader::kBindingLoopStats, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, b.loopStats.Handle()}},
                          "pathtrace", 2 * sizeof(uint32_t));
  ClearSums(ctx_, b);
  return MakeGpuFrame(ctx_, std::move(b), std::move(pipeline), std::move(kernels), p, options);
}

RenderResult GpuRenderer::Render(const shader::FrameParams& frame, const GpuRenderOptions& options) {
  std::unique_ptr<FrameRenderer> f = BeginFrame(frame, options);
  auto t0 = std::chrono::steady_clock::now();
  f->AddSamples(frame.sampleBegin, frame.sampleCount, {}, options.progress);
  const FrameSums sums = f->Sums();
  RenderResult result;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  result.image = ResolveFilm(sums);
  result.rays = sums.rays;
  result.nonFinite = sums.nonFinite;
  result.cutShort = sums.cutShort;
  const RunState& state = GpuFrameState(*f);
  result.batches = state.batches;
  result.samplesPerInvocation = state.samplesPerInvocation;
  result.engine = f->Engine();
  return result;
}

std::vector<shader::HitRecord> GpuRenderer::Trace(const std::vector<shader::RayQuery>& rays, double* seconds) {
  if (rays.empty()) return {};
  Buffer rayBuffer = Upload(ctx_, rays, "rays");
  Buffer hits = StorageBuffer(ctx_, rays.size() * sizeof(shader::HitRecord), "hits");
  ComputePipeline pipeline(ctx_, traceSpirv_.data(), traceSpirv_.size_bytes(),
                           {TexelBinding(shader::kBindingTriangles, triangles_.low),
                            TexelBinding(shader::kBindingTrianglesHigh, triangles_.high),
                            TexelBinding(shader::kBindingNodes, nodes_),
                            {shader::kBindingRays, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, rayBuffer.Handle()},
                            {shader::kBindingHits, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, hits.Handle()}},
                           "trace", 3 * sizeof(uint32_t), {triangles_.twoBuffers ? 1u : 0u});
  const uint32_t push[3] = {nodeCount_, nodeCopies_, triangles_.split};
  Buffer hitsHost = ReadbackBuffer(ctx_, hits.Size(), "hits readback");
  const uint32_t groups = uint32_t((rays.size() + 63) / 64);
  auto t0 = std::chrono::steady_clock::now();
  ctx_.Submit([&](VkCommandBuffer cb) {
    ComputeBarrier(cb);
    pipeline.Dispatch(cb, groups, 1, 1, push);
  });
  if (seconds) *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ctx_.Submit([&](VkCommandBuffer cb) { CopyToHost(cb, {{&hits, &hitsHost}}); });
  const auto* h = static_cast<const shader::HitRecord*>(hitsHost.Mapped());
  return std::vector<shader::HitRecord>(h, h + rays.size());
}

}  // namespace vkpt::internal::vk

#include "vk/vk_renderer.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <memory>
#include <numeric>
#include <string>

#include "kAovSpirv.h"
#include "kPathTraceSpirv.h"
#include "kTraceSpirv.h"
#include "shared/bsdf.h"
#include "util/byte_size.h"
#include "util/error.h"
#include "vk/compute_pipeline.h"
#include "vk/vk_check.h"

namespace vkpt::vk {
namespace {

constexpr uint32_t kWorkgroup = 8;  // pathtrace.comp: local_size 8×8

template <class T>
Buffer Upload(const Context& ctx, const std::vector<T>& v, const char* what) {
  return UploadStorage(ctx, v.data(), v.size() * sizeof(T), what);
}

template <class T>
TexelBuffer UploadArray(const Context& ctx, std::span<const T> v, const char* what) {
  return UploadTexelBuffer(ctx, v.data(), v.size() * sizeof(T), what);
}

// An array of whole-texel structs, in two texel buffers if one cannot hold it.
template <class T>
SplitTexelBuffer UploadSplitArray(const Context& ctx, std::span<const T> v, const char* what,
                                  uint32_t maxTexelsPerBuffer) {
  static_assert(sizeof(T) % 16 == 0);
  return UploadSplitTexelBuffer(ctx, v.data(), v.size() * sizeof(T), sizeof(T) / 16, what, maxTexelsPerBuffer);
}

// Samples per invocation for a scene whose worst SIMD group needed `passesPerSample` loop
// passes per sample in the last submission: a quarter of lavapipe's loop budget, so that
// a run of unluckier samples still fits (a group past the budget is reported as cut
// short, never silent). A run averages its samples' passes, so longer runs measure fewer
// per sample and the run may grow from one submission to the next. At most 32: longer
// runs measured no gain (docs/design-notes.md, "GPU path regeneration").
uint32_t RunLength(uint32_t passesPerSample) {
  return std::clamp<uint32_t>(shader::kLoopBudget / 4 / std::max(passesPerSample, 1u), 1u, 32u);
}

// A stride for dealing out n rows of tiles to rows of workgroups (pathtrace.comp): close
// to n / φ, so that any run of consecutive rows samples the image evenly (a Weyl
// sequence), and coprime to n, so that each row is rendered exactly once. Past 65535
// (Vulkan's minimum workgroup count per dimension), n · stride could overflow the
// shader's 32-bit product: stride 1, in order.
uint32_t TileRowStride(uint32_t n) {
  if (n > 65535) return 1;
  uint32_t stride = std::max(1u, uint32_t(n * 0.6180339887));
  while (std::gcd(stride, n) != 1) ++stride;
  return stride;
}

// pathtrace.comp's per-render buffers: per pixel Σf and Σf² (two vec4), the counters
// (rays, non-finite samples, samples cut short, samples) and the adaptive sampling mask;
// the frame constants; the loop passes per sample of the last submission's worst SIMD
// group; host copies of the sums and counters.
struct FrameBuffers {
  Buffer accum, counters, active, params, loopStats, accumHost, countersHost;
};

Buffer HostVisible(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, const char* what) {
  return Buffer(ctx, size, usage, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, what);
}

FrameBuffers MakeFrameBuffers(const Context& ctx, uint64_t pixels) {
  FrameBuffers b;
  b.accum = StorageBuffer(ctx, pixels * 2 * sizeof(glm::vec4), "accumulation");
  b.counters = StorageBuffer(ctx, pixels * sizeof(glm::uvec4), "counter");
  b.active = HostVisible(ctx, pixels * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "active pixels");
  b.params = HostVisible(ctx, sizeof(shader::FrameParams), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, "frame params");
  b.loopStats = HostVisible(ctx, sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "loop statistics");
  b.accumHost = ReadbackBuffer(ctx, b.accum.Size(), "accumulation readback");
  b.countersHost = ReadbackBuffer(ctx, b.counters.Size(), "counter readback");
  return b;
}

// Samples per pixel per submission: options.batch, or about 2^20 paths.
uint32_t BatchSize(const GpuRenderOptions& options, uint64_t pixels, uint32_t count) {
  if (options.batch) return std::min(options.batch, count);
  return uint32_t(std::clamp<uint64_t>((1u << 20) / std::max<uint64_t>(pixels, 1), 1, std::max(count, 1u)));
}

// How a frame's dispatches have gone so far: the run of samples per invocation, and
// whether a dispatch has measured the scene's loop passes yet.
struct RunState {
  uint32_t run = 1;
  bool measured = false;
  uint32_t batches = 0;               // submissions
  uint32_t samplesPerInvocation = 0;  // the longest run used
};

// Adds samples [begin, begin + count) of `frame` into b.accum and b.counters: submissions
// of `BatchSize` samples per pixel, each a series of dispatches of `run` samples per
// invocation.
void DispatchSamples(const Context& ctx, const ComputePipeline& pipeline, const FrameBuffers& b,
                     const shader::FrameParams& frame, uint32_t begin, uint32_t count, const GpuRenderOptions& options,
                     RunState& state, const std::function<void(double)>& progress) {
  const uint32_t batch = BatchSize(options, uint64_t(frame.width) * frame.height, count);
  const uint32_t groupsX = (frame.width + kWorkgroup - 1) / kWorkgroup;
  const uint32_t groupsY = (frame.height + kWorkgroup - 1) / kWorkgroup;
  for (uint32_t done = 0; done < count;) {
    shader::FrameParams p = frame;
    p.sampleBegin = begin + done;
    // Until a dispatch has measured the scene's loop passes, one sample per invocation,
    // and the first submission holds just that one dispatch.
    p.sampleCount = state.measured ? std::min(batch, count - done) : 1u;
    std::memcpy(b.params.Mapped(), &p, sizeof p);            // the previous batch has finished: safe to overwrite
    std::memset(b.loopStats.Mapped(), 0, sizeof(uint32_t));  // measure this submission's runs alone
    const uint32_t run = state.run;
    ctx.Submit([&](VkCommandBuffer cb) {
      for (uint32_t s = 0; s < p.sampleCount; s += run) {
        ComputeBarrier(cb);  // each dispatch adds to what the previous one wrote
        const uint32_t push[2] = {s, std::min(run, p.sampleCount - s)};
        pipeline.Dispatch(cb, groupsX, groupsY, 1, push);
      }
      HostReadBarrier(cb);  // for loopStats
    });
    state.samplesPerInvocation = std::max(state.samplesPerInvocation, std::min(run, p.sampleCount));
    if (!options.samplesPerInvocation) state.run = RunLength(*static_cast<const uint32_t*>(b.loopStats.Mapped()));
    state.measured = true;
    done += p.sampleCount;
    ++state.batches;
    if (progress) progress(double(done) / count);
  }
}

}  // namespace

GpuRenderer::GpuRenderer(const Context& ctx, const RenderScene& scene, const GpuRendererOverrides& overrides)
    : ctx_(ctx),
      pathTraceSpirv_(overrides.pathTraceSpirv.empty() ? std::span<const uint32_t>(kPathTraceSpirv)
                                                       : overrides.pathTraceSpirv),
      traceSpirv_(overrides.traceSpirv.empty() ? std::span<const uint32_t>(kTraceSpirv) : overrides.traceSpirv),
      triangles_(UploadSplitArray<shader::Triangle>(ctx, scene.triangles, "triangles", overrides.maxTexelsPerBuffer)),
      nodes_(UploadArray<shader::BvhNode>(ctx, scene.nodes, "BVH nodes")),
      materials_(UploadArray<shader::Material>(ctx, scene.materials, "materials")),
      lights_(UploadArray<shader::Light>(ctx, scene.lights, "lights")),
      ggxAlbedo_(UploadArray<float>(ctx, shader::kGgxAlbedo, "GGX albedo table")),
      shading_(UploadArray<shader::TriangleShading>(ctx, scene.shading, "shading normals")),
      vertexColors_(UploadArray<shader::TriangleColors>(ctx, scene.vertexColors, "vertex colours")),
      uvs_(UploadSplitArray<shader::TriangleUVs>(ctx, scene.uvs, "texture coordinates", overrides.maxTexelsPerBuffer)),
      tangents_(UploadArray<shader::TriangleTangents>(ctx, scene.tangents, "tangents")),
      textureRefs_(UploadArray<shader::TextureRef>(ctx, scene.textureRefs, "material textures")),
      textures_(UploadArray<shader::Texture>(ctx, scene.textures, "texture table")),
      texels_(UploadSplitTexelBuffer(ctx, scene.texels.data(), scene.texels.size() * sizeof(uint32_t), 1,
                                     "texture texels", overrides.maxTexelsPerBuffer)),
      texelDecode_(UploadArray<float>(ctx, scene.texelDecode, "texel decode tables")),
      envRadiance_(UploadArray<glm::vec4>(ctx, scene.environment.texels, "environment map texels")),
      envDistribution_(UploadArray<float>(ctx, scene.environment.cdf, "environment map CDFs")),
      hasGlossy_(UsesGlossyMaterial(scene)),
      hasSmoothNormals_(
          std::any_of(scene.shading.begin(), scene.shading.end(),
                      [](const shader::TriangleShading& s) { return (s.flags & shader::kShadingHasNormals) != 0; })),
      hasVertexColors_(!scene.vertexColors.empty()),
      hasVolumes_(UsesVolumeMaterial(scene)),
      hasTextures_(!scene.textureRefs.empty()),
      hasNormalMaps_(!scene.tangents.empty()),
      hasAlpha_(scene.alphaTested),
      hasExtensionTextures_(
          std::any_of(scene.materials.begin(), scene.materials.end(),
                      [](const shader::Material& m) { return (m.flags & shader::kMaterialExtensionTextured) != 0u; })),
      nodeCount_(scene.bvhStats.nodes),
      nodeCopies_(scene.nodeCopies) {
  for (const shader::Light& l : scene.lights) lightTypes_ |= 1u << l.type;
}

std::vector<BufferBinding> GpuRenderer::SceneBindings() const {
  return {TexelBinding(shader::kBindingTriangles, triangles_.low),
          TexelBinding(shader::kBindingTrianglesHigh, triangles_.high),
          TexelBinding(shader::kBindingNodes, nodes_),
          TexelBinding(shader::kBindingMaterials, materials_),
          TexelBinding(shader::kBindingLights, lights_),
          TexelBinding(shader::kBindingGgxAlbedo, ggxAlbedo_),
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
          uvs_.twoBuffers ? 1u : 0u};
}

namespace {

// A kernel over the scene (scene_constants.glsl) with the given per-frame bindings.
using KernelFactory = std::function<std::unique_ptr<ComputePipeline>(const uint32_t* spirv, size_t spirvBytes,
                                                                     std::vector<BufferBinding> frameBindings,
                                                                     const char* name, uint32_t pushConstantBytes)>;

// Zeroes a frame's sums and counters on the device.
void ClearSums(const Context& ctx, const FrameBuffers& b) {
  ctx.Submit([&](VkCommandBuffer cb) {
    vkCmdFillBuffer(cb, b.accum.Handle(), 0, VK_WHOLE_SIZE, 0);
    vkCmdFillBuffer(cb, b.counters.Handle(), 0, VK_WHOLE_SIZE, 0);
  });
}

// A render in progress on the device: the frame's buffers and pipeline, kept from pass
// to pass, so the sums persist in device memory exactly as within one pass.
class GpuFrame final : public FrameRenderer {
 public:
  GpuFrame(const Context& ctx, FrameBuffers b, std::unique_ptr<ComputePipeline> pipeline, KernelFactory kernels,
           const shader::FrameParams& frame, const GpuRenderOptions& options)
      : ctx_(ctx),
        b_(std::move(b)),
        pipeline_(std::move(pipeline)),
        kernels_(std::move(kernels)),
        frame_(frame),
        options_(options) {
    frame_.tileRowStride = TileRowStride((frame.height + kWorkgroup - 1) / kWorkgroup);
    if (options.samplesPerInvocation) {
      state_.run = options.samplesPerInvocation;
      state_.measured = true;
    }
  }

  void AddSamples(uint32_t begin, uint32_t count, std::span<const uint8_t> active,
                  const std::function<void(double)>& progress) override {
    frame_.adaptive = active.empty() ? 0u : 1u;
    if (!active.empty()) {
      auto* mask = static_cast<uint32_t*>(b_.active.Mapped());
      for (size_t i = 0; i < active.size(); ++i) mask[i] = active[i];
    }
    DispatchSamples(ctx_, *pipeline_, b_, frame_, begin, count, options_, state_, progress);
  }

  FrameSums Sums() override {
    ctx_.Submit([&](VkCommandBuffer cb) {
      CopyToHost(cb, {{&b_.accum, &b_.accumHost}, {&b_.counters, &b_.countersHost}});
    });
    const auto* sums = static_cast<const glm::vec4*>(b_.accumHost.Mapped());
    const auto* count = static_cast<const glm::uvec4*>(b_.countersHost.Mapped());
    FrameSums f;
    f.width = frame_.width;
    f.height = frame_.height;
    f.pixels.resize(size_t(f.width) * f.height);
    for (size_t i = 0; i < f.pixels.size(); ++i) {
      f.pixels[i] = {glm::dvec3(glm::vec3(sums[2 * i])), glm::dvec3(glm::vec3(sums[2 * i + 1])), count[i].w};
      f.rays += count[i].x;
      f.nonFinite += count[i].y;
      f.cutShort += count[i].z;
    }
    return f;
  }

  void Clear() override { ClearSums(ctx_, b_); }

  AovSums RenderAovs(uint32_t samples) override {
    const uint64_t pixels = uint64_t(frame_.width) * frame_.height;
    Buffer sums = StorageBuffer(ctx_, pixels * shader::kAovSumsPerPixel * sizeof(glm::vec4), "AOV sum");
    Buffer sumsHost = ReadbackBuffer(ctx_, sums.Size(), "AOV readback");
    std::unique_ptr<ComputePipeline> aov =
        kernels_(kAovSpirv, sizeof(kAovSpirv),
                 {{shader::kBindingParams, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, b_.params.Handle()},
                  {shader::kBindingAovSums, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, sums.Handle()}},
                 "aov", sizeof(uint32_t));
    std::memcpy(b_.params.Mapped(), &frame_, sizeof frame_);  // every earlier submission has finished
    ctx_.Submit([&](VkCommandBuffer cb) {
      vkCmdFillBuffer(cb, sums.Handle(), 0, VK_WHOLE_SIZE, 0);
      for (uint32_t s = 0; s < samples; ++s) {
        ComputeBarrier(cb);  // each dispatch adds to what the previous one wrote
        aov->Dispatch(cb, (frame_.width + kWorkgroup - 1) / kWorkgroup, (frame_.height + kWorkgroup - 1) / kWorkgroup,
                      1, &s);
      }
      CopyToHost(cb, {{&sums, &sumsHost}});
    });
    const auto* v = static_cast<const glm::vec4*>(sumsHost.Mapped());
    AovSums a;
    a.width = frame_.width;
    a.height = frame_.height;
    a.samples = samples;
    a.pixels.resize(pixels);
    for (size_t i = 0; i < pixels; ++i) {
      const glm::vec4* p = v + shader::kAovSumsPerPixel * i;
      a.pixels[i] = {glm::dvec3(glm::vec3(p[0])),
                     glm::dvec3(glm::vec3(p[1])),
                     glm::dvec3(glm::vec3(p[2])),
                     double(p[0].w),
                     double(p[2].w),
                     uint32_t(p[1].w)};
    }
    return a;
  }

  std::string Engine() const override {
    return "vulkan: " + ctx_.DeviceName() + " (up to " + std::to_string(state_.samplesPerInvocation) +
           " samples per invocation)";
  }
  const RunState& State() const { return state_; }

 private:
  const Context& ctx_;
  FrameBuffers b_;
  std::unique_ptr<ComputePipeline> pipeline_;
  KernelFactory kernels_;
  shader::FrameParams frame_;
  const GpuRenderOptions options_;
  RunState state_;
};

}  // namespace

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
                          {{shader::kBindingParams, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, b.params.Handle()},
                           {shader::kBindingAccum, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, b.accum.Handle()},
                           {shader::kBindingCounters, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, b.counters.Handle()},
                           {shader::kBindingActive, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, b.active.Handle()},
                           {shader::kBindingLoopStats, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, b.loopStats.Handle()}},
                          "pathtrace", 2 * sizeof(uint32_t));
  ClearSums(ctx_, b);
  return std::make_unique<GpuFrame>(ctx_, std::move(b), std::move(pipeline), std::move(kernels), p, options);
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
  const RunState& state = static_cast<const GpuFrame&>(*f).State();
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

}  // namespace vkpt::vk

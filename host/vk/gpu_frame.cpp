#include "vk/gpu_frame.h"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <string>

#include "kAovSpirv.h"
#include "vk/vk_check.h"

namespace vkpt::internal::vk {
namespace {

constexpr uint32_t kWorkgroup = 8;  // pathtrace.comp: local_size 8×8

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

Buffer HostVisible(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, const char* what) {
  return Buffer(ctx, size, usage, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, what);
}

// Samples per pixel per submission: options.batch, or about 2^20 paths.
uint32_t BatchSize(const GpuRenderOptions& options, uint64_t pixels, uint32_t count) {
  if (options.batch) return std::min(options.batch, count);
  return uint32_t(std::clamp<uint64_t>((1u << 20) / std::max<uint64_t>(pixels, 1), 1, std::max(count, 1u)));
}

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

  void AddSumsTo(FrameSums& into) override {
    ctx_.Submit([&](VkCommandBuffer cb) {
      CopyToHost(cb, {{&b_.accum, &b_.accumHost}, {&b_.counters, &b_.countersHost}});
    });
    const auto* sums = static_cast<const glm::vec4*>(b_.accumHost.Mapped());
    const auto* count = static_cast<const glm::uvec4*>(b_.countersHost.Mapped());
    SizeToAdd(into, frame_.width, frame_.height);
    for (size_t i = 0; i < into.pixels.size(); ++i) {
      PixelSums& p = into.pixels[i];
      p.sum += glm::dvec3(glm::vec3(sums[2 * i]));
      p.sumOfSquares += glm::dvec3(glm::vec3(sums[2 * i + 1]));
      p.samples += count[i].w;
      into.rays += count[i].x;
      into.nonFinite += count[i].y;
      into.cutShort += count[i].z;
    }
  }

  void Clear() override { ClearSums(ctx_, b_); }

  AovSums RenderAovs(const AovRequest& request) override {
    const uint64_t pixels = uint64_t(frame_.width) * frame_.height;
    Buffer sums = StorageBuffer(ctx_, pixels * shader::kAovSumsPerPixel * sizeof(glm::vec4), "AOV sum");
    Buffer sumsHost = ReadbackBuffer(ctx_, sums.Size(), "AOV readback");
    // Without ids the shader writes no triangle: one uint stands in for the binding.
    Buffer triangles = StorageBuffer(ctx_, (request.ids ? pixels : 1) * sizeof(uint32_t), "AOV triangle");
    Buffer trianglesHost = ReadbackBuffer(ctx_, triangles.Size(), "AOV triangle readback");
    std::unique_ptr<ComputePipeline> aov =
        kernels_(kAovSpirv, sizeof(kAovSpirv),
                 {FrameParamsBinding(b_),
                  {shader::kBindingAovSums, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, sums.Handle()},
                  {shader::kBindingAovTriangles, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, triangles.Handle()}},
                 "aov", 2 * sizeof(uint32_t));
    std::memcpy(b_.params.Mapped(), &frame_, sizeof frame_);  // every earlier submission has finished
    ctx_.Submit([&](VkCommandBuffer cb) {
      vkCmdFillBuffer(cb, sums.Handle(), 0, VK_WHOLE_SIZE, 0);
      vkCmdFillBuffer(cb, triangles.Handle(), 0, VK_WHOLE_SIZE, shader::kInvalidIndex);
      for (uint32_t s = 0; s < request.samples; ++s) {
        ComputeBarrier(cb);  // each dispatch adds to what the previous one wrote
        const uint32_t push[2] = {s, request.ids};
        aov->Dispatch(cb, (frame_.width + kWorkgroup - 1) / kWorkgroup, (frame_.height + kWorkgroup - 1) / kWorkgroup,
                      1, push);
      }
      CopyToHost(cb, {{&sums, &sumsHost}, {&triangles, &trianglesHost}});
    });
    const auto* v = static_cast<const glm::vec4*>(sumsHost.Mapped());
    const auto* t = static_cast<const uint32_t*>(trianglesHost.Mapped());
    AovSums a;
    a.width = frame_.width;
    a.height = frame_.height;
    a.samples = request.samples;
    a.pixels.resize(pixels);
    for (size_t i = 0; i < pixels; ++i) {
      const glm::vec4* p = v + shader::kAovSumsPerPixel * i;
      a.pixels[i] = {glm::dvec3(glm::vec3(p[0])),
                     glm::dvec3(glm::vec3(p[1])),
                     glm::dvec3(glm::vec3(p[2])),
                     double(p[0].w),
                     double(p[2].w),
                     uint32_t(p[1].w),
                     request.ids ? t[i] : shader::kInvalidIndex};
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

FrameBuffers MakeFrameBuffers(const Context& ctx, uint64_t pixels) {
  FrameBuffers b;
  b.accum = StorageBuffer(ctx, pixels * 2 * sizeof(glm::vec4), "accumulation");
  b.counters = StorageBuffer(ctx, pixels * sizeof(glm::uvec4), "counter");
  b.active = HostVisible(ctx, pixels * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "active pixels");
  b.params = HostVisible(ctx, sizeof(shader::FrameParams), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "frame params");
  b.loopStats = HostVisible(ctx, sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "loop statistics");
  b.accumHost = ReadbackBuffer(ctx, b.accum.Size(), "accumulation readback");
  b.countersHost = ReadbackBuffer(ctx, b.counters.Size(), "counter readback");
  return b;
}

BufferBinding FrameParamsBinding(const FrameBuffers& b) {
  return {shader::kBindingParams, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, b.params.Handle()};
}

void ClearSums(const Context& ctx, const FrameBuffers& b) {
  ctx.Submit([&](VkCommandBuffer cb) {
    vkCmdFillBuffer(cb, b.accum.Handle(), 0, VK_WHOLE_SIZE, 0);
    vkCmdFillBuffer(cb, b.counters.Handle(), 0, VK_WHOLE_SIZE, 0);
  });
}

std::unique_ptr<FrameRenderer> MakeGpuFrame(const Context& ctx, FrameBuffers b,
                                            std::unique_ptr<ComputePipeline> pipeline, KernelFactory kernels,
                                            const shader::FrameParams& frame, const GpuRenderOptions& options) {
  return std::make_unique<GpuFrame>(ctx, std::move(b), std::move(pipeline), std::move(kernels), frame, options);
}

const RunState& GpuFrameState(const FrameRenderer& frame) { return static_cast<const GpuFrame&>(frame).State(); }

}  // namespace vkpt::internal::vk

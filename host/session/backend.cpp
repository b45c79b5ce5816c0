#include "session/backend.h"

#include <chrono>

#include "cpu/path_tracer.h"
#include "vk/vk_denoise.h"

namespace vkpt {

RenderBackend::RenderBackend(const vk::Context* ctx, const RenderScene& rs, const shader::FrameParams& params,
                             uint32_t batch, unsigned threads)
    : ctx_(ctx), threads_(threads) {
  if (!ctx) {
    frame_ = BeginCpuFrame(rs, params, threads);
    return;
  }
  const auto t0 = std::chrono::steady_clock::now();
  gpu_ = std::make_unique<vk::GpuRenderer>(*ctx, rs);
  vk::GpuRenderOptions options;
  options.batch = batch;
  frame_ = gpu_->BeginFrame(params, options);
  uploadSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

Denoiser RenderBackend::MakeDenoiser() const {
  if (ctx_) return [ctx = ctx_](const DenoiseInput& input) { return vk::AtrousGpu(*ctx, input); };
  return [threads = threads_](const DenoiseInput& input) { return AtrousCpu(input, threads); };
}

}  // namespace vkpt

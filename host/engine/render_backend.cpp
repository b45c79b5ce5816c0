#include "engine/render_backend.h"

#include "cpu/path_tracer.h"
#include "vk/vk_denoise.h"

namespace vkpt::internal {

RenderBackend::RenderBackend(const vk::Context* ctx, const RenderScene& rs, unsigned threads)
    : ctx_(ctx), rs_(rs), threads_(threads) {
  if (ctx) gpu_ = std::make_unique<vk::GpuRenderer>(*ctx, rs);
}

std::unique_ptr<FrameRenderer> RenderBackend::BeginFrame(const shader::FrameParams& params, uint32_t batch) const {
  if (!gpu_) return BeginCpuFrame(rs_, params, threads_);
  vk::GpuRenderOptions options;
  options.batch = batch;
  return gpu_->BeginFrame(params, options);
}

void RenderBackend::Restyle(bool triangleLights) {
  if (gpu_) gpu_->Restyle(rs_, triangleLights);
}

Denoiser RenderBackend::MakeDenoiser() const {
  if (ctx_)
    return [ctx = ctx_](const DenoiseInput& input, const StopFilter& stop) { return vk::AtrousGpu(*ctx, input, stop); };
  return [threads = threads_](const DenoiseInput& input, const StopFilter& stop) {
    return AtrousCpu(input, threads, stop);
  };
}

}  // namespace vkpt::internal

#include "vk/vk_denoise.h"

#include <memory>

#include "kDenoiseSpirv.h"
#include "shared/layout.h"
#include "vk/buffer.h"
#include "vk/compute_pipeline.h"

namespace vkpt::internal::vk {

std::optional<std::vector<glm::vec4>> AtrousGpu(const Context& ctx, const DenoiseInput& input, const StopFilter& stop) {
  const VkDeviceSize bytes = input.color.size() * sizeof(glm::vec4);
  Buffer color[2] = {UploadStorage(ctx, input.color.data(), bytes, "denoiser colour"),
                     StorageBuffer(ctx, bytes, "denoiser colour")};
  const Buffer guide = UploadStorage(ctx, input.guide.data(), bytes, "denoiser guide");
  const Buffer albedo = UploadStorage(ctx, input.albedo.data(), bytes, "denoiser albedo");
  // Iteration i reads color[i % 2] and writes the other.
  auto pipeline = [&](int from) {
    return std::make_unique<ComputePipeline>(
        ctx, kDenoiseSpirv, sizeof(kDenoiseSpirv),
        std::vector<BufferBinding>{
            {shader::kBindingDenoiseColor, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, color[from].Handle()},
            {shader::kBindingDenoiseGuide, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, guide.Handle()},
            {shader::kBindingDenoiseAlbedo, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, albedo.Handle()},
            {shader::kBindingDenoiseOut, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, color[1 - from].Handle()}},
        "denoise", 3 * sizeof(uint32_t));
  };
  const std::unique_ptr<ComputePipeline> pipelines[2] = {pipeline(0), pipeline(1)};
  const Buffer host = ReadbackBuffer(ctx, bytes, "denoiser readback");
  const uint32_t last = shader::kDenoiseIterations % 2;  // the buffer the last iteration wrote
  // Each submission ends before the next begins, so an iteration reads the last one's output.
  for (uint32_t it = 0; it < shader::kDenoiseIterations; ++it) {
    if (stop && stop()) return std::nullopt;
    ctx.Submit([&](VkCommandBuffer cb) {
      const uint32_t push[3] = {input.width, input.height, it};
      pipelines[it % 2]->Dispatch(cb, (input.width + 7) / 8, (input.height + 7) / 8, 1, push);
      if (it + 1 == shader::kDenoiseIterations) CopyToHost(cb, {{&color[last], &host}});
    });
  }
  const auto* v = static_cast<const glm::vec4*>(host.Mapped());
  return std::vector<glm::vec4>(v, v + input.color.size());
}

}  // namespace vkpt::internal::vk

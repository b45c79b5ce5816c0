// A compute pipeline with one descriptor set of buffers (set 0): shader module, layouts,
// pool and set, owned together.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "vk/context.h"

namespace vkpt::vk {

struct BufferBinding {
  uint32_t binding;
  VkDescriptorType type;  // STORAGE_BUFFER or UNIFORM_BUFFER
  VkBuffer buffer;
};

class ComputePipeline {
 public:
  ComputePipeline(const Context& ctx, const uint32_t* spirv, size_t spirvBytes,
                  const std::vector<BufferBinding>& bindings, const std::string& name);
  ~ComputePipeline();
  ComputePipeline(const ComputePipeline&) = delete;
  ComputePipeline& operator=(const ComputePipeline&) = delete;

  // Binds the pipeline and its set and records a dispatch.
  void Dispatch(VkCommandBuffer cb, uint32_t x, uint32_t y, uint32_t z) const;

 private:
  void Destroy();
  const Context& ctx_;
  VkShaderModule module_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
};

// A barrier making all earlier transfer and compute writes visible to later compute
// reads and writes (also across submissions, which by themselves order nothing in memory).
void ComputeBarrier(VkCommandBuffer cb);

}  // namespace vkpt::vk

// A compute pipeline with one descriptor set of buffers and texel buffers (set 0): the
// compiled pipeline comes from the device's PipelineCache (pipeline_cache.h), the pool
// and set that bind this pipeline's buffers are its own.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "vk/buffer.h"
#include "vk/context.h"

namespace vkpt::internal::vk {

struct BufferBinding {
  uint32_t binding;
  VkDescriptorType type;  // STORAGE_BUFFER or UNIFORM_TEXEL_BUFFER
  VkBuffer buffer;        // the buffer types
  VkBufferView view = VK_NULL_HANDLE;  // UNIFORM_TEXEL_BUFFER
};

inline BufferBinding TexelBinding(uint32_t binding, const TexelBuffer& t) {
  return {binding, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, t.buffer.Handle(), t.view.Handle()};
}

class ComputePipeline {
 public:
  // `pushConstantBytes` > 0 declares a push-constant block of that size (compute stage).
  // `specialization[i]` is the value of the 32-bit specialization constant constant_id = i.
  ComputePipeline(const Context& ctx, const uint32_t* spirv, size_t spirvBytes,
                  const std::vector<BufferBinding>& bindings, const std::string& name,
                  uint32_t pushConstantBytes = 0, const std::vector<uint32_t>& specialization = {});
  ~ComputePipeline();
  ComputePipeline(const ComputePipeline&) = delete;
  ComputePipeline& operator=(const ComputePipeline&) = delete;

  // Binds the pipeline and its set, pushes `push` (pushConstantBytes of it) if given,
  // and records a dispatch.
  void Dispatch(VkCommandBuffer cb, uint32_t x, uint32_t y, uint32_t z, const void* push = nullptr) const;

 private:
  void Destroy();
  const Context& ctx_;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  uint32_t pushConstantBytes_ = 0;
};

// A barrier making all earlier transfer and compute writes visible to later compute
// reads and writes (also across submissions, which by themselves order nothing in memory).
void ComputeBarrier(VkCommandBuffer cb);

// A barrier making earlier compute writes to host-visible memory readable by the host
// once the submission's fence has signalled.
void HostReadBarrier(VkCommandBuffer cb);

// Copies device buffers to host-visible ones after compute writes, with the barriers
// that make the data visible to the host once the submission's fence has signalled.
class Buffer;
void CopyToHost(VkCommandBuffer cb, const std::vector<std::pair<const Buffer*, const Buffer*>>& srcDst);

}  // namespace vkpt::internal::vk

// The compiled compute pipelines of one device, kept for the device's lifetime and
// shared by every renderer made on it: a frame sequence, or many renders of one scene,
// compiles each kernel once, not once per frame (on lavapipe a path-tracing kernel takes
// 1.4–1.8 s to compile). A pipeline is found by all that compiling depends on: the
// SPIR-V words, the bindings' numbers and types, the push-constant size and the
// specialization constants; the buffers bound are not part of it (each ComputePipeline
// has its own descriptor set). VkPipelineCache would not do: lavapipe keeps no compiled
// code in it.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <mutex>
#include <vector>

namespace vkpt::internal::vk {

struct CompiledPipeline {
  VkShaderModule module = VK_NULL_HANDLE;
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
};

class Context;

class PipelineCache {
 public:
  explicit PipelineCache(VkDevice device) : device_(device) {}
  ~PipelineCache();  // destroys every pipeline; the device must be idle
  PipelineCache(const PipelineCache&) = delete;
  PipelineCache& operator=(const PipelineCache&) = delete;

  // The pipeline for these inputs, compiled on first use (named `name` for validation
  // messages). `bindingTypes` holds (binding, VkDescriptorType) pairs.
  const CompiledPipeline& Get(const Context& ctx, const uint32_t* spirv, size_t spirvBytes,
                              const std::vector<std::pair<uint32_t, VkDescriptorType>>& bindingTypes, const char* name,
                              uint32_t pushConstantBytes, const std::vector<uint32_t>& specialization);

  size_t Compiled() const { return compiled_; }  // pipelines compiled so far

 private:
  VkDevice device_;
  std::mutex mutex_;
  std::map<std::vector<uint32_t>, CompiledPipeline> pipelines_;
  size_t compiled_ = 0;
};

}  // namespace vkpt::internal::vk

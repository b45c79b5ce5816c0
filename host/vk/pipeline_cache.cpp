#include "vk/pipeline_cache.h"

#include "vk/context.h"
#include "vk/vk_check.h"

namespace vkpt::internal::vk {
namespace {

VkShaderModule CreateShaderModule(VkDevice dev, const uint32_t* spirv, size_t spirvBytes) {
  VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  moduleInfo.codeSize = spirvBytes;
  moduleInfo.pCode = spirv;
  VkShaderModule module = VK_NULL_HANDLE;
  VKPT_VK_CHECK(vkCreateShaderModule(dev, &moduleInfo, nullptr, &module));
  return module;
}

// Set 0: one descriptor per binding, for the compute stage.
VkDescriptorSetLayout CreateDescriptorLayout(VkDevice dev,
                                             const std::vector<std::pair<uint32_t, VkDescriptorType>>& bindings) {
  std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
  for (const auto& [binding, type] : bindings)
    layoutBindings.push_back({binding, type, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.bindingCount = uint32_t(layoutBindings.size());
  setInfo.pBindings = layoutBindings.data();
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VKPT_VK_CHECK(vkCreateDescriptorSetLayout(dev, &setInfo, nullptr, &setLayout));
  return setLayout;
}

VkPipelineLayout CreatePipelineLayout(VkDevice dev, VkDescriptorSetLayout setLayout, uint32_t pushConstantBytes) {
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &setLayout;
  VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushConstantBytes};
  if (pushConstantBytes) {
    layoutInfo.pushConstantRangeCount = 1;
    layoutInfo.pPushConstantRanges = &range;
  }
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VKPT_VK_CHECK(vkCreatePipelineLayout(dev, &layoutInfo, nullptr, &layout));
  return layout;
}

// `specialization[i]` becomes the 32-bit specialization constant constant_id = i.
VkPipeline CreatePipeline(VkDevice dev, VkShaderModule module, VkPipelineLayout layout,
                          const std::vector<uint32_t>& specialization) {
  VkComputePipelineCreateInfo pipeInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  pipeInfo.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  pipeInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  pipeInfo.stage.module = module;
  pipeInfo.stage.pName = "main";
  std::vector<VkSpecializationMapEntry> entries(specialization.size());
  for (uint32_t i = 0; i < entries.size(); ++i) entries[i] = {i, i * uint32_t(sizeof(uint32_t)), sizeof(uint32_t)};
  VkSpecializationInfo specInfo{uint32_t(entries.size()), entries.data(), specialization.size() * sizeof(uint32_t),
                                specialization.data()};
  if (!specialization.empty()) pipeInfo.stage.pSpecializationInfo = &specInfo;
  pipeInfo.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VKPT_VK_CHECK(vkCreateComputePipelines(dev, VK_NULL_HANDLE, 1, &pipeInfo, nullptr, &pipeline));
  return pipeline;
}

void Destroy(VkDevice dev, const CompiledPipeline& c) {
  if (c.pipeline) vkDestroyPipeline(dev, c.pipeline, nullptr);
  if (c.layout) vkDestroyPipelineLayout(dev, c.layout, nullptr);
  if (c.setLayout) vkDestroyDescriptorSetLayout(dev, c.setLayout, nullptr);
  if (c.module) vkDestroyShaderModule(dev, c.module, nullptr);
}

}  // namespace

PipelineCache::~PipelineCache() {
  for (const auto& [key, compiled] : pipelines_) Destroy(device_, compiled);
}

const CompiledPipeline& PipelineCache::Get(const Context& ctx, const uint32_t* spirv, size_t spirvBytes,
                                           const std::vector<std::pair<uint32_t, VkDescriptorType>>& bindingTypes,
                                           const char* name, uint32_t pushConstantBytes,
                                           const std::vector<uint32_t>& specialization) {
  // The key: the small parts first, so that most lookups differ early, then the SPIR-V.
  std::vector<uint32_t> key = {pushConstantBytes, uint32_t(bindingTypes.size()), uint32_t(specialization.size())};
  for (const auto& [binding, type] : bindingTypes) key.insert(key.end(), {binding, uint32_t(type)});
  key.insert(key.end(), specialization.begin(), specialization.end());
  key.insert(key.end(), spirv, spirv + spirvBytes / sizeof(uint32_t));
  std::lock_guard<std::mutex> lock(mutex_);
  if (const auto it = pipelines_.find(key); it != pipelines_.end()) return it->second;
  CompiledPipeline c;
  try {
    c.module = CreateShaderModule(device_, spirv, spirvBytes);
    ctx.Name(VK_OBJECT_TYPE_SHADER_MODULE, uint64_t(c.module), name);
    c.setLayout = CreateDescriptorLayout(device_, bindingTypes);
    c.layout = CreatePipelineLayout(device_, c.setLayout, pushConstantBytes);
    c.pipeline = CreatePipeline(device_, c.module, c.layout, specialization);
    ctx.Name(VK_OBJECT_TYPE_PIPELINE, uint64_t(c.pipeline), name);
  } catch (...) {
    Destroy(device_, c);  // a handle whose creation threw is still null
    throw;
  }
  ++compiled_;
  return pipelines_.emplace(std::move(key), c).first->second;
}

}  // namespace vkpt::internal::vk

#include "vk/compute_pipeline.h"

#include <map>

#include "vk/buffer.h"
#include "vk/vk_check.h"

namespace vkpt::vk {
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
VkDescriptorSetLayout CreateDescriptorLayout(VkDevice dev, const std::vector<BufferBinding>& bindings) {
  std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
  for (const BufferBinding& b : bindings)
    layoutBindings.push_back({b.binding, b.type, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
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

// A pool holding exactly one set of `bindings`: as many descriptors of each type as
// they have.
VkDescriptorPool CreateDescriptorPool(VkDevice dev, const std::vector<BufferBinding>& bindings) {
  std::map<VkDescriptorType, uint32_t> perType;
  for (const BufferBinding& b : bindings) ++perType[b.type];
  std::vector<VkDescriptorPoolSize> sizes;
  for (auto [type, count] : perType) sizes.push_back({type, count});
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = 1;
  poolInfo.poolSizeCount = uint32_t(sizes.size());
  poolInfo.pPoolSizes = sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VKPT_VK_CHECK(vkCreateDescriptorPool(dev, &poolInfo, nullptr, &pool));
  return pool;
}

VkDescriptorSet AllocateDescriptorSet(VkDevice dev, VkDescriptorPool pool, VkDescriptorSetLayout setLayout) {
  VkDescriptorSetAllocateInfo allocInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  allocInfo.descriptorPool = pool;
  allocInfo.descriptorSetCount = 1;
  allocInfo.pSetLayouts = &setLayout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  VKPT_VK_CHECK(vkAllocateDescriptorSets(dev, &allocInfo, &set));
  return set;
}

// Points each binding of `set` at its whole buffer, or at its texel buffer view.
void WriteDescriptorSet(VkDevice dev, VkDescriptorSet set, const std::vector<BufferBinding>& bindings) {
  std::vector<VkDescriptorBufferInfo> infos(bindings.size());
  std::vector<VkWriteDescriptorSet> writes(bindings.size());
  for (size_t i = 0; i < bindings.size(); ++i) {
    infos[i] = {bindings[i].buffer, 0, VK_WHOLE_SIZE};
    writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[i].dstSet = set;
    writes[i].dstBinding = bindings[i].binding;
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = bindings[i].type;
    if (bindings[i].type == VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER) writes[i].pTexelBufferView = &bindings[i].view;
    else writes[i].pBufferInfo = &infos[i];
  }
  vkUpdateDescriptorSets(dev, uint32_t(writes.size()), writes.data(), 0, nullptr);
}

}  // namespace

ComputePipeline::ComputePipeline(const Context& ctx, const uint32_t* spirv, size_t spirvBytes,
                                 const std::vector<BufferBinding>& bindings, const std::string& name,
                                 uint32_t pushConstantBytes, const std::vector<uint32_t>& specialization)
    : ctx_(ctx), pushConstantBytes_(pushConstantBytes) {
  VkDevice dev = ctx.Device();
  try {
    module_ = CreateShaderModule(dev, spirv, spirvBytes);
    ctx.Name(VK_OBJECT_TYPE_SHADER_MODULE, uint64_t(module_), name.c_str());
    setLayout_ = CreateDescriptorLayout(dev, bindings);
    layout_ = CreatePipelineLayout(dev, setLayout_, pushConstantBytes);
    pipeline_ = CreatePipeline(dev, module_, layout_, specialization);
    ctx.Name(VK_OBJECT_TYPE_PIPELINE, uint64_t(pipeline_), name.c_str());
    pool_ = CreateDescriptorPool(dev, bindings);
    set_ = AllocateDescriptorSet(dev, pool_, setLayout_);
    WriteDescriptorSet(dev, set_, bindings);
  } catch (...) {
    // Destroys what was made so far; a handle whose creation threw is still null.
    Destroy();
    throw;
  }
}

ComputePipeline::~ComputePipeline() { Destroy(); }

void ComputePipeline::Destroy() {
  VkDevice dev = ctx_.Device();
  if (pool_) vkDestroyDescriptorPool(dev, pool_, nullptr);  // frees set_
  if (pipeline_) vkDestroyPipeline(dev, pipeline_, nullptr);
  if (layout_) vkDestroyPipelineLayout(dev, layout_, nullptr);
  if (setLayout_) vkDestroyDescriptorSetLayout(dev, setLayout_, nullptr);
  if (module_) vkDestroyShaderModule(dev, module_, nullptr);
  pool_ = VK_NULL_HANDLE;
  pipeline_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
  setLayout_ = VK_NULL_HANDLE;
  module_ = VK_NULL_HANDLE;
}

void ComputePipeline::Dispatch(VkCommandBuffer cb, uint32_t x, uint32_t y, uint32_t z, const void* push) const {
  vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
  vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set_, 0, nullptr);
  if (push && pushConstantBytes_) vkCmdPushConstants(cb, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, pushConstantBytes_, push);
  vkCmdDispatch(cb, x, y, z);
}

void ComputeBarrier(VkCommandBuffer cb) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
  vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

void HostReadBarrier(VkCommandBuffer cb) {
  VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr,
                       0, nullptr);
}

void CopyToHost(VkCommandBuffer cb, const std::vector<std::pair<const Buffer*, const Buffer*>>& srcDst) {
  VkMemoryBarrier toTransfer{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  toTransfer.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
  toTransfer.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &toTransfer, 0, nullptr, 0, nullptr);
  for (const auto& [src, dst] : srcDst) {
    VkBufferCopy region{0, 0, src->Size()};
    vkCmdCopyBuffer(cb, src->Handle(), dst->Handle(), 1, &region);
  }
  VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0,
                       nullptr);
}

}  // namespace vkpt::vk

#include "vk/compute_pipeline.h"

#include <map>

#include "vk/buffer.h"
#include "vk/pipeline_cache.h"
#include "vk/vk_check.h"

namespace vkpt::internal::vk {
namespace {

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
    std::vector<std::pair<uint32_t, VkDescriptorType>> types;
    for (const BufferBinding& b : bindings) types.emplace_back(b.binding, b.type);
    const CompiledPipeline& compiled =
        ctx.Pipelines().Get(ctx, spirv, spirvBytes, types, name.c_str(), pushConstantBytes, specialization);
    layout_ = compiled.layout;
    pipeline_ = compiled.pipeline;
    pool_ = CreateDescriptorPool(dev, bindings);
    set_ = AllocateDescriptorSet(dev, pool_, compiled.setLayout);
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
  if (pool_) vkDestroyDescriptorPool(dev, pool_, nullptr);  // frees set_; the pipeline is the cache's
  pool_ = VK_NULL_HANDLE;
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

}  // namespace vkpt::internal::vk

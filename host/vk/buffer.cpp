#include "vk/buffer.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include "util/byte_size.h"
#include "util/error.h"
#include "vk/vk_check.h"

namespace vkpt::internal::vk {
namespace {


uint32_t FindMemoryType(const Context& ctx, uint32_t typeBits, VkMemoryPropertyFlags want, const std::string& what) {
  const VkPhysicalDeviceMemoryProperties& mp = ctx.MemoryProperties();
  for (uint32_t i = 0; i < mp.memoryTypeCount; ++i)
    if ((typeBits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) return i;
  throw Error("Vulkan: no memory type for the " + what + " buffer on " + ctx.DeviceName());
}

// At least one 16-byte texel and a whole number of them (Vulkan has no empty buffers, and
// a TexelView then covers every byte), filled through a staging buffer.
Buffer UploadDeviceLocal(const Context& ctx, const void* data, size_t bytes, VkBufferUsageFlags usage,
                         const std::string& what) {
  const VkDeviceSize size = std::max<VkDeviceSize>((bytes + 15) / 16 * 16, 16);
  Buffer staging(ctx, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                 VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, what + " (staging)");
  std::memset(staging.Mapped(), 0, size);
  if (bytes) std::memcpy(staging.Mapped(), data, bytes);
  Buffer device(ctx, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, what);
  ctx.Submit([&](VkCommandBuffer cb) {
    VkBufferCopy region{0, 0, size};
    vkCmdCopyBuffer(cb, staging.Handle(), device.Handle(), 1, &region);
  });
  return device;
}

}  // namespace

Buffer::Buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, VkMemoryPropertyFlags memory,
               const std::string& what)
    : ctx_(&ctx), size_(size) {
  try {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VKPT_VK_CHECK(vkCreateBuffer(ctx.Device(), &info, nullptr, &buffer_));
    ctx.Name(VK_OBJECT_TYPE_BUFFER, uint64_t(buffer_), what.c_str());
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(ctx.Device(), buffer_, &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = FindMemoryType(ctx, req.memoryTypeBits, memory, what);
    VkResult r = vkAllocateMemory(ctx.Device(), &alloc, nullptr, &memory_);
    if (r == VK_ERROR_OUT_OF_DEVICE_MEMORY || r == VK_ERROR_OUT_OF_HOST_MEMORY)
      throw Error("Vulkan: out of memory allocating the " + what + " buffer (" + FormatBytes(size) + ") on " + ctx.DeviceName());
    VKPT_VK_CHECK(r);
    VKPT_VK_CHECK(vkBindBufferMemory(ctx.Device(), buffer_, memory_, 0));
    if (memory & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)
      VKPT_VK_CHECK(vkMapMemory(ctx.Device(), memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
  } catch (...) {
    Release();
    throw;
  }
}

Buffer::~Buffer() { Release(); }

Buffer::Buffer(Buffer&& o) noexcept { *this = std::move(o); }

Buffer& Buffer::operator=(Buffer&& o) noexcept {
  if (this != &o) {
    Release();
    ctx_ = std::exchange(o.ctx_, nullptr);
    buffer_ = std::exchange(o.buffer_, VK_NULL_HANDLE);
    memory_ = std::exchange(o.memory_, VK_NULL_HANDLE);
    size_ = std::exchange(o.size_, 0);
    mapped_ = std::exchange(o.mapped_, nullptr);
  }
  return *this;
}

void Buffer::Release() {
  if (!ctx_) return;
  if (buffer_) vkDestroyBuffer(ctx_->Device(), buffer_, nullptr);
  if (memory_) vkFreeMemory(ctx_->Device(), memory_, nullptr);  // unmaps implicitly
  buffer_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  mapped_ = nullptr;
}

Buffer UploadStorage(const Context& ctx, const void* data, size_t bytes, const std::string& what) {
  const VkDeviceSize limit = ctx.Properties().limits.maxStorageBufferRange;
  if (bytes > limit)
    throw Error("the scene's " + what + " buffer needs " + FormatBytes(bytes) + ", but " + ctx.DeviceName() +
                " allows at most " + FormatBytes(limit) +
                " per storage buffer (maxStorageBufferRange); render this scene with --backend cpu");
  return UploadDeviceLocal(ctx, data, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, what);
}

TexelBuffer UploadTexelBuffer(const Context& ctx, const void* data, size_t bytes, const std::string& what) {
  const uint64_t texels = (bytes + 15) / 16;
  const uint32_t limit = ctx.Properties().limits.maxTexelBufferElements;
  if (texels > limit)
    throw Error("the scene's " + what + " need " + std::to_string(texels) + " texels of 16 bytes, but " +
                ctx.DeviceName() + " allows at most " + std::to_string(limit) +
                " per texel buffer (maxTexelBufferElements); render this scene with --backend cpu");
  TexelBuffer t;
  t.buffer = UploadDeviceLocal(ctx, data, bytes, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT, what);
  t.view = TexelView(ctx, t.buffer, what);
  return t;
}

SplitTexelBuffer UploadSplitTexelBuffer(const Context& ctx, const void* data, size_t bytes, uint32_t texelsPerElement,
                                        const std::string& what, uint32_t maxTexelsPerBuffer) {
  const uint32_t limit = ctx.Properties().limits.maxTexelBufferElements;
  const uint64_t perBuffer = maxTexelsPerBuffer ? std::min(maxTexelsPerBuffer, limit) : limit;
  const uint64_t elementBytes = uint64_t(texelsPerElement) * 16;
  const uint64_t elements = (bytes + elementBytes - 1) / elementBytes;
  const uint64_t elementsPerBuffer = std::max<uint64_t>(perBuffer / texelsPerElement, 1);
  SplitTexelBuffer s;
  s.twoBuffers = elements > elementsPerBuffer;
  s.split = uint32_t(std::min(elements, elementsPerBuffer));
  if (elements - s.split > limit / texelsPerElement)
    throw Error("the scene's " + what + " need " + std::to_string(elements * texelsPerElement) +
                " texels of 16 bytes, more than two texel buffers hold on " + ctx.DeviceName() + " (at most " +
                std::to_string(limit) + " texels each, maxTexelBufferElements); render this scene with --backend cpu");
  const size_t lowBytes = std::min<size_t>(bytes, size_t(s.split * elementBytes));
  s.low = UploadTexelBuffer(ctx, data, lowBytes, what);
  s.high =
      UploadTexelBuffer(ctx, static_cast<const uint8_t*>(data) + lowBytes, bytes - lowBytes, what + " (second buffer)");
  return s;
}

TexelView::TexelView(const Context& ctx, const Buffer& buffer, const std::string& what) : ctx_(&ctx) {
  constexpr VkFormat kFormat = VK_FORMAT_R32G32B32A32_UINT;
  VkFormatProperties fp;
  vkGetPhysicalDeviceFormatProperties(ctx.PhysicalDevice(), kFormat, &fp);
  if (!(fp.bufferFeatures & VK_FORMAT_FEATURE_UNIFORM_TEXEL_BUFFER_BIT))
    throw Error("Vulkan: " + ctx.DeviceName() + " cannot read RGBA32UI uniform texel buffers");
  VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
  info.buffer = buffer.Handle();
  info.format = kFormat;
  info.offset = 0;
  info.range = VK_WHOLE_SIZE;
  VKPT_VK_CHECK(vkCreateBufferView(ctx.Device(), &info, nullptr, &view_));
  ctx.Name(VK_OBJECT_TYPE_BUFFER_VIEW, uint64_t(view_), what.c_str());
}

TexelView::~TexelView() { Release(); }

TexelView::TexelView(TexelView&& o) noexcept { *this = std::move(o); }

TexelView& TexelView::operator=(TexelView&& o) noexcept {
  if (this != &o) {
    Release();
    ctx_ = std::exchange(o.ctx_, nullptr);
    view_ = std::exchange(o.view_, VK_NULL_HANDLE);
  }
  return *this;
}

void TexelView::Release() {
  if (ctx_ && view_) vkDestroyBufferView(ctx_->Device(), view_, nullptr);
  view_ = VK_NULL_HANDLE;
}

Buffer StorageBuffer(const Context& ctx, VkDeviceSize size, const std::string& what) {
  const VkDeviceSize limit = ctx.Properties().limits.maxStorageBufferRange;
  if (size > limit)
    throw Error("the image needs a " + FormatBytes(size) + " " + what + " buffer, but " + ctx.DeviceName() +
                " allows at most " + FormatBytes(limit) +
                " per storage buffer (maxStorageBufferRange); use a smaller --width/--height or --backend cpu");
  return Buffer(
      ctx, size,
      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
      VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, what);
}

Buffer ReadbackBuffer(const Context& ctx, VkDeviceSize size, const std::string& what) {
  return Buffer(ctx, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, what);
}

}  // namespace vkpt::internal::vk

// A VkBuffer with its own memory allocation. Device-local buffers are filled through a
// staging buffer; host-visible ones are mapped for their whole life.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <string>

#include "vk/context.h"

namespace vkpt::vk {

class Buffer {
 public:
  Buffer() = default;
  // `what` names the buffer in errors ("triangles") and debug names.
  Buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, VkMemoryPropertyFlags memory,
         const std::string& what);
  ~Buffer();
  Buffer(Buffer&& o) noexcept;
  Buffer& operator=(Buffer&& o) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  VkBuffer Handle() const { return buffer_; }
  VkDeviceSize Size() const { return size_; }
  void* Mapped() const { return mapped_; }  // null unless host-visible

 private:
  void Release();
  const Context* ctx_ = nullptr;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
};

// A device-local storage buffer holding `bytes` (at least 4 bytes: Vulkan has no empty
// buffers). Uploads through a staging buffer.
Buffer UploadStorage(const Context& ctx, const void* data, size_t bytes, const std::string& what);

}  // namespace vkpt::vk

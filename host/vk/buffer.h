// A VkBuffer with its own memory allocation. Device-local buffers are filled through a
// staging buffer; host-visible ones are mapped for their whole life.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <span>
#include <string>

#include "vk/context.h"

namespace vkpt::internal::vk {

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

// A device-local storage buffer holding `bytes`, uploaded through a staging buffer;
// checked against maxStorageBufferRange.
Buffer UploadStorage(const Context& ctx, const void* data, size_t bytes, const std::string& what);

// A device-local storage buffer of `size` bytes for the image's sums (also a transfer
// source and destination), checked against maxStorageBufferRange with a message naming
// the fix; and a host-visible, coherent one that such buffers are copied into.
Buffer StorageBuffer(const Context& ctx, VkDeviceSize size, const std::string& what);
Buffer ReadbackBuffer(const Context& ctx, VkDeviceSize size, const std::string& what);

// A view of a whole buffer as a uniform texel buffer of RGBA32UI texels (16 bytes), which
// shaders read with texelFetch. Checks that the device supports the format for that.
class TexelView {
 public:
  TexelView() = default;
  TexelView(const Context& ctx, const Buffer& buffer, const std::string& what);
  ~TexelView();
  TexelView(TexelView&& o) noexcept;
  TexelView& operator=(TexelView&& o) noexcept;
  TexelView(const TexelView&) = delete;
  TexelView& operator=(const TexelView&) = delete;

  VkBufferView Handle() const { return view_; }

 private:
  void Release();
  const Context* ctx_ = nullptr;
  VkBufferView view_ = VK_NULL_HANDLE;
};

// A device-local buffer and its texel view, uploaded through a staging buffer; checked
// against maxTexelBufferElements.
struct TexelBuffer {
  Buffer buffer;
  TexelView view;
};
TexelBuffer UploadTexelBuffer(const Context& ctx, const void* data, size_t bytes, const std::string& what);

// An array of elements of `texelsPerElement` RGBA32UI texels in one texel buffer, or in
// two when one cannot hold it: the first `split` elements in `low`, the rest in `high` (a
// 1-texel dummy when one suffices). No element straddles the two, so a shader reads each
// from one buffer. Texels per buffer: at most maxTexelsPerBuffer, 0 meaning the device's
// maxTexelBufferElements (tests pass fewer, to split small arrays); past two buffers the
// upload is refused, naming that limit.
struct SplitTexelBuffer {
  TexelBuffer low, high;
  uint32_t split = 0;
  bool twoBuffers = false;
};
SplitTexelBuffer UploadSplitTexelBuffer(const Context& ctx, const void* data, size_t bytes, uint32_t texelsPerElement,
                                        const std::string& what, uint32_t maxTexelsPerBuffer = 0);

}  // namespace vkpt::internal::vk

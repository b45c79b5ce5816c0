// Where a frame's pixels wait on the device before the blit to the window: a host-visible
// buffer the caller's bytes are copied into, and an RGBA8 image of the same size that the
// buffer is copied to (vkCmdBlitImage needs an image as its source; a linear-tiled image
// that can be blitted from is not guaranteed to exist, an optimal one is).
#pragma once

#include <cstdint>

#include "vk/vk_check.h"
#include "window/present_device.h"

namespace vkpt::internal {

class StagingImage {
 public:
  // The RGBA8 pixels the copies move: R8G8B8A8_UNORM, so that the bytes pass unchanged.
  static constexpr VkFormat kFormat = VK_FORMAT_R8G8B8A8_UNORM;

  StagingImage(const PresentDevice& device, uint32_t width, uint32_t height);
  ~StagingImage();
  StagingImage(const StagingImage&) = delete;
  StagingImage& operator=(const StagingImage&) = delete;

  uint32_t Width() const { return width_; }
  uint32_t Height() const { return height_; }
  VkBuffer Buffer() const { return buffer_; }
  VkImage Image() const { return image_; }
  // The buffer's bytes, mapped for the object's life (host-coherent: no flush needed).
  uint8_t* Mapped() const { return mapped_; }

 private:
  void Release();

  const PresentDevice& device_;
  uint32_t width_, height_;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory bufferMemory_ = VK_NULL_HANDLE;
  uint8_t* mapped_ = nullptr;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory imageMemory_ = VK_NULL_HANDLE;
};

}  // namespace vkpt::internal

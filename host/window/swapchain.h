// The window's swapchain: its images, their views and framebuffers for the overlay's
// render pass, and one "rendered" semaphore per image for presentation to wait on.
//
// Format: B8G8R8A8_UNORM or R8G8B8A8_UNORM, never an _SRGB one, so the bytes the caller
// gives (already display-encoded) reach the screen unchanged. Present mode: MAILBOX if
// the surface has it (no tearing, no waiting for vblank), else IMMEDIATE (may tear, no
// waiting), else FIFO (always there; waits for vblank): a viewer wants the latest frame
// on screen soonest, and Show() must not block its render loop.
#pragma once

#include <cstdint>
#include <vector>

#include "vk/vk_check.h"
#include "window/present_device.h"

namespace vkpt::internal {

class Swapchain {
 public:
  // Chooses the format and present mode (throws Error when the surface offers no UNORM
  // 8-bit format or cannot be a transfer destination), creates the overlay's render pass
  // and a swapchain for a framebuffer of `framebuffer` pixels.
  Swapchain(const PresentDevice& device, VkExtent2D framebuffer);
  ~Swapchain();
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;

  // A new swapchain for `framebuffer` (the old one retired through oldSwapchain); waits
  // for the device to be idle first, as the old images may still be in use.
  void Recreate(VkExtent2D framebuffer);

  VkSwapchainKHR Handle() const { return swapchain_; }
  VkFormat Format() const { return format_.format; }
  VkPresentModeKHR PresentMode() const { return presentMode_; }
  // The images' size: the surface's current extent, which may lag behind GLFW's
  // framebuffer size right after a resize.
  VkExtent2D Extent() const { return extent_; }
  // The framebuffer size this swapchain was made for (what Show compares to detect a resize).
  VkExtent2D Requested() const { return requested_; }
  uint32_t MinImageCount() const { return minImageCount_; }
  uint32_t ImageCount() const { return uint32_t(images_.size()); }
  VkImage Image(uint32_t i) const { return images_[i]; }
  VkFramebuffer Framebuffer(uint32_t i) const { return framebuffers_[i]; }
  VkSemaphore Rendered(uint32_t i) const { return rendered_[i]; }
  // One subpass drawing over the blitted image: loadOp LOAD from COLOR_ATTACHMENT_OPTIMAL,
  // leaving it in PRESENT_SRC_KHR.
  VkRenderPass RenderPass() const { return renderPass_; }

 private:
  void Create(VkExtent2D framebuffer);
  void CreateImageObjects();
  void DestroyImages();
  void Release();

  const PresentDevice& device_;
  VkSurfaceFormatKHR format_{};
  VkPresentModeKHR presentMode_ = VK_PRESENT_MODE_FIFO_KHR;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkExtent2D extent_{}, requested_{};
  uint32_t minImageCount_ = 2;
  std::vector<VkImage> images_;
  std::vector<VkImageView> views_;
  std::vector<VkFramebuffer> framebuffers_;
  std::vector<VkSemaphore> rendered_;
};

}  // namespace vkpt::internal

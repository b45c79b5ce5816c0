// Dear ImGui on the window: its context (dark style, no imgui.ini written), the GLFW
// backend (input, with GLFW's callbacks chained) and the Vulkan backend, which draws in
// the swapchain's render pass over the blitted picture.
//
// ImGui has one current context per process, and GLFW one state: one Overlay (one
// Presenter) at a time.
#pragma once

#include <cstdint>

#include "vk/vk_check.h"
#include "window/present_device.h"
#include "window/swapchain.h"

struct GLFWwindow;

namespace vkpt::internal {

class Overlay {
 public:
  // Creates the context and both backends, and uploads the font atlas (waiting for it).
  Overlay(GLFWwindow* window, const PresentDevice& device, const Swapchain& swapchain);
  ~Overlay();
  Overlay(const Overlay&) = delete;
  Overlay& operator=(const Overlay&) = delete;

  // Starts an ImGui frame (the Vulkan backend's, GLFW's, then ImGui::NewFrame); a frame
  // begun and never drawn is ended first.
  void Begin();
  // Ends a begun frame without drawing it (a minimised window shows nothing).
  void Discard();
  // Records the render pass over `framebuffer`: ImGui's draw data if a frame was begun
  // (ImGui::Render, then the draw calls), else nothing but the pass's layout change to
  // PRESENT_SRC_KHR.
  void Record(VkCommandBuffer cb, VkRenderPass pass, VkFramebuffer framebuffer, VkExtent2D extent);
  // After a swapchain is recreated with another minimum image count.
  void SetMinImageCount(uint32_t count);

 private:
  void UploadFonts(const PresentDevice& device);
  void Release();

  VkDevice device_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  bool context_ = false, glfw_ = false, vulkan_ = false;
  bool begun_ = false;
};

}  // namespace vkpt::internal

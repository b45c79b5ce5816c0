// The Vulkan objects a window presents through: an instance with the surface extensions
// GLFW asks for, the window's surface, a device with one queue that can both draw (the
// overlay's render pass) and present to that surface, and the validation messenger.
// It is the presenter's own: vk::Context (host/vk/context.h) is headless and its instance
// has no surface extensions.
#pragma once

#include <cstdint>
#include <string>

#include "vk/instance.h"
#include "vk/vk_check.h"

struct GLFWwindow;

namespace vkpt::internal {

class PresentDevice {
 public:
  // The first device with a graphics queue that can present to `window`'s surface and the
  // VK_KHR_swapchain extension, or the first whose name contains `device` when that is not
  // empty. With `validation`, VK_LAYER_KHRONOS_validation (synchronization validation on)
  // reports warnings and errors to stderr and counts them. Throws Error when no device can
  // present, naming the devices it saw.
  PresentDevice(GLFWwindow* window, const std::string& device, bool validation);
  ~PresentDevice();
  PresentDevice(const PresentDevice&) = delete;
  PresentDevice& operator=(const PresentDevice&) = delete;

  VkInstance Instance() const { return instance_; }
  VkSurfaceKHR Surface() const { return surface_; }
  VkPhysicalDevice Physical() const { return physical_; }
  VkDevice Device() const { return device_; }
  VkQueue Queue() const { return queue_; }
  uint32_t QueueFamily() const { return queueFamily_; }
  const std::string& Name() const { return name_; }
  uint32_t ValidationMessages() const { return validation_.Count(); }

  // A memory type among `typeBits` with `want` (throws Error when there is none).
  uint32_t MemoryType(uint32_t typeBits, VkMemoryPropertyFlags want) const;

 private:
  void Destroy();

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  std::string name_;
  vk::ValidationCounter validation_{"vkpt: viewer validation"};
};

}  // namespace vkpt::internal

#include "window/present_device.h"

#include <cstdio>
#include <cstring>
#include <optional>
#include <vector>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "util/error.h"
#include "vk/instance.h"
#include "vk/vk_check.h"

namespace vkpt::internal {
namespace {

// An instance with the extensions GLFW needs for a surface on this platform (xcb or
// xlib on X11, wayland); the rest as vk::CreateInstance makes it.
VkInstance CreateInstance(bool validation, bool debugUtils, const VkDebugUtilsMessengerCreateInfoEXT* messengerInfo) {
  uint32_t glfwCount = 0;
  const char** glfwExtensions = glfwGetRequiredInstanceExtensions(&glfwCount);
  if (!glfwExtensions) throw Error("GLFW finds no Vulkan surface extensions for this window system");
  return vk::CreateInstance(validation, debugUtils, messengerInfo, {glfwExtensions, glfwCount});
}

bool HasSwapchainExtension(VkPhysicalDevice d) {
  uint32_t n = 0;
  vkEnumerateDeviceExtensionProperties(d, nullptr, &n, nullptr);
  std::vector<VkExtensionProperties> exts(n);
  vkEnumerateDeviceExtensionProperties(d, nullptr, &n, exts.data());
  for (const VkExtensionProperties& e : exts)
    if (std::strcmp(e.extensionName, VK_KHR_SWAPCHAIN_EXTENSION_NAME) == 0) return true;
  return false;
}

// A queue family of `d` that has graphics (and so transfer) and can present to `surface`.
std::optional<uint32_t> PresentQueueFamily(VkPhysicalDevice d, VkSurfaceKHR surface) {
  if (!HasSwapchainExtension(d)) return std::nullopt;
  uint32_t n = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(d, &n, nullptr);
  std::vector<VkQueueFamilyProperties> families(n);
  vkGetPhysicalDeviceQueueFamilyProperties(d, &n, families.data());
  for (uint32_t i = 0; i < n; ++i) {
    VkBool32 present = VK_FALSE;
    if (vkGetPhysicalDeviceSurfaceSupportKHR(d, i, surface, &present) != VK_SUCCESS) continue;
    if ((families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && present) return i;
  }
  return std::nullopt;
}

}  // namespace

PresentDevice::PresentDevice(GLFWwindow* window, const std::string& device, bool validation) {
  try {
    const bool debugUtils = vk::CheckDebugUtils(validation);
    const VkDebugUtilsMessengerCreateInfoEXT messengerInfo = validation_.Info();
    instance_ = CreateInstance(validation, debugUtils, &messengerInfo);
    if (validation) messenger_ = vk::CreateMessenger(instance_, messengerInfo);
    VKPT_VK_CHECK(glfwCreateWindowSurface(instance_, window, nullptr, &surface_));

    uint32_t n = 0;
    VKPT_VK_CHECK(vkEnumeratePhysicalDevices(instance_, &n, nullptr));
    std::vector<VkPhysicalDevice> devices(n);
    VKPT_VK_CHECK(vkEnumeratePhysicalDevices(instance_, &n, devices.data()));
    if (n == 0) throw Error(std::string("no Vulkan device found; ") + vk::kNoDeviceFix);
    std::string seen;
    for (VkPhysicalDevice d : devices) {
      VkPhysicalDeviceProperties props;
      vkGetPhysicalDeviceProperties(d, &props);
      seen += std::string(seen.empty() ? "" : ", ") + props.deviceName;
      if (!device.empty() && std::string(props.deviceName).find(device) == std::string::npos) continue;
      const std::optional<uint32_t> family = PresentQueueFamily(d, surface_);
      if (!family) continue;
      physical_ = d, queueFamily_ = *family, name_ = props.deviceName;
      break;
    }
    if (!physical_) {
      const std::string which = device.empty() ? "no Vulkan device" : "no Vulkan device named \"" + device + "\"";
      throw Error(which + " can present to the window (devices: " + seen + ")");
    }
    const char* swapchain[] = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
    device_ = vk::CreateDevice(physical_, queueFamily_, swapchain);
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
  } catch (...) {
    Destroy();
    throw;
  }
}

PresentDevice::~PresentDevice() { Destroy(); }

void PresentDevice::Destroy() {
  if (device_) vkDestroyDevice(device_, nullptr);
  if (surface_) vkDestroySurfaceKHR(instance_, surface_, nullptr);
  if (messenger_) vk::DestroyMessenger(instance_, messenger_);
  if (instance_) vkDestroyInstance(instance_, nullptr);
  device_ = VK_NULL_HANDLE, surface_ = VK_NULL_HANDLE, messenger_ = VK_NULL_HANDLE, instance_ = VK_NULL_HANDLE;
}

uint32_t PresentDevice::MemoryType(uint32_t typeBits, VkMemoryPropertyFlags want) const {
  VkPhysicalDeviceMemoryProperties props;
  vkGetPhysicalDeviceMemoryProperties(physical_, &props);
  for (uint32_t i = 0; i < props.memoryTypeCount; ++i)
    if ((typeBits & (1u << i)) && (props.memoryTypes[i].propertyFlags & want) == want) return i;
  throw Error("the Vulkan device " + name_ + " has no memory type for the viewer's images");
}

}  // namespace vkpt::internal

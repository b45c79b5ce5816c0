// The Vulkan instance and device a Context (context.h) starts from, and the viewer's
// presenter (window/present_device.h) too, with the validation layer and its debug
// messenger when asked for.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <span>

namespace vkpt::internal::vk {

// How to get a Vulkan device where the loader finds none, for the messages that say so.
inline constexpr const char* kNoDeviceFix =
    "install a Vulkan driver: on Debian, `apt-get install mesa-vulkan-drivers` gives lavapipe, "
    "a software Vulkan device on the CPU";

// Whether the loader has VK_EXT_debug_utils. With `validation`, throws Error when
// the validation layer or debug utils are missing.
bool CheckDebugUtils(bool validation);

// Validation's warnings and errors: each printed to stderr after `prefix` and counted.
// It must outlive the messenger made from its Info().
class ValidationCounter {
 public:
  explicit ValidationCounter(const char* prefix) : prefix_(prefix) {}
  // The messenger of validation: warnings and errors of every type, to this counter.
  VkDebugUtilsMessengerCreateInfoEXT Info();
  uint32_t Count() const { return count_.load(); }

 private:
  static VKAPI_ATTR VkBool32 VKAPI_CALL OnMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                  VkDebugUtilsMessageTypeFlagsEXT types,
                                                  const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);
  const char* prefix_;
  std::atomic<uint32_t> count_{0};
};

// A Vulkan 1.2 instance with `extensions` (a window's surface extensions; debug utils
// with `debugUtils`); with `validation`, the validation layer with synchronization
// validation and `messengerInfo` for the messages of instance creation itself. Throws
// Error (saying how to get a device) when there is no driver, and naming the extensions
// when the driver lacks one.
VkInstance CreateInstance(bool validation, bool debugUtils, const VkDebugUtilsMessengerCreateInfoEXT* messengerInfo,
                          std::span<const char* const> extensions = {});

// The logical device of `physical`, with one queue of `queueFamily` and `extensions`.
VkDevice CreateDevice(VkPhysicalDevice physical, uint32_t queueFamily, std::span<const char* const> extensions = {});

VkDebugUtilsMessengerEXT CreateMessenger(VkInstance instance, const VkDebugUtilsMessengerCreateInfoEXT& info);
void DestroyMessenger(VkInstance instance, VkDebugUtilsMessengerEXT messenger);

}  // namespace vkpt::internal::vk

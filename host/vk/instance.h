// The Vulkan instance a Context (context.h) starts from, with the validation layer and
// its debug messenger when asked for.
#pragma once

#include <vulkan/vulkan.h>

namespace vkpt::internal::vk {

// How to get a Vulkan device where the loader finds none, for the messages that say so.
inline constexpr const char* kNoDeviceFix =
    "install a Vulkan driver: on Debian, `apt-get install mesa-vulkan-drivers` gives lavapipe, "
    "a software Vulkan device on the CPU";

// Whether the loader has VK_EXT_debug_utils. With `validation`, throws Error when
// the validation layer or debug utils are missing.
bool CheckDebugUtils(bool validation);

// The messenger of validation: warnings and errors of every type, to `callback` with `user`.
VkDebugUtilsMessengerCreateInfoEXT MessengerInfo(PFN_vkDebugUtilsMessengerCallbackEXT callback, void* user);

// A Vulkan 1.2 instance; with `validation`, the validation layer with synchronization
// validation and `messengerInfo` for the messages of instance creation itself. Throws
// Error (saying how to get a device) when there is no driver.
VkInstance CreateInstance(bool validation, bool debugUtils, const VkDebugUtilsMessengerCreateInfoEXT* messengerInfo);

VkDebugUtilsMessengerEXT CreateMessenger(VkInstance instance, const VkDebugUtilsMessengerCreateInfoEXT& info);
void DestroyMessenger(VkInstance instance, VkDebugUtilsMessengerEXT messenger);

}  // namespace vkpt::internal::vk

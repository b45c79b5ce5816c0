// Every VkResult is checked; a failure throws Error naming the call and the code.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

namespace vkpt::internal::vk {

const char* ResultName(VkResult r);

// Throws Error("Vulkan: <call> failed: <VK_ERROR_...>") unless r is VK_SUCCESS.
void Check(VkResult r, const char* call);

}  // namespace vkpt::internal::vk

#define VKPT_VK_CHECK(call) ::vkpt::internal::vk::Check((call), #call)

// Every VkResult is checked; a failure throws vkpt::Error naming the call and the code.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

namespace vkpt::vk {

const char* ResultName(VkResult r);

// Throws vkpt::Error("Vulkan: <call> failed: <VK_ERROR_...>") unless r is VK_SUCCESS.
void Check(VkResult r, const char* call);

}  // namespace vkpt::vk

#define VKPT_VK_CHECK(call) ::vkpt::vk::Check((call), #call)

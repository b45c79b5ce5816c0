#include "vk/vk_check.h"

#include "util/error.h"

namespace vkpt::internal::vk {

const char* ResultName(VkResult r) {
  switch (r) {
#define VKPT_CASE(x) case x: return #x;
    VKPT_CASE(VK_SUCCESS)
    VKPT_CASE(VK_NOT_READY)
    VKPT_CASE(VK_TIMEOUT)
    VKPT_CASE(VK_INCOMPLETE)
    VKPT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    VKPT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    VKPT_CASE(VK_ERROR_INITIALIZATION_FAILED)
    VKPT_CASE(VK_ERROR_DEVICE_LOST)
    VKPT_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    VKPT_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    VKPT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    VKPT_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    VKPT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    VKPT_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    VKPT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    VKPT_CASE(VK_ERROR_FRAGMENTED_POOL)
    VKPT_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    VKPT_CASE(VK_ERROR_INVALID_SHADER_NV)
#undef VKPT_CASE
    default: return "VkResult error";
  }
}

void Check(VkResult r, const char* call) {
  if (r == VK_SUCCESS) return;
  std::string hint;
  if (r == VK_ERROR_OUT_OF_DEVICE_MEMORY || r == VK_ERROR_OUT_OF_HOST_MEMORY)
    hint = " (the scene or image is too large for this device's memory)";
  else if (r == VK_ERROR_DEVICE_LOST)
    hint = " (the device was lost: a driver fault or a watchdog timeout; try a smaller --batch)";
  throw Error(std::string("Vulkan: ") + call + " failed: " + ResultName(r) + " (" + std::to_string(int(r)) + ")" + hint);
}

}  // namespace vkpt::internal::vk

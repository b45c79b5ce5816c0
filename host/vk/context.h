// Vulkan instance, device and compute queue: everything a headless compute renderer
// needs and nothing more (no window, no swapchain). Handles are owned RAII-style and
// destroyed in reverse order of creation.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "vk/instance.h"
#include "vk/pipeline_cache.h"

namespace vkpt::internal::vk {

struct DeviceInfo {
  uint32_t index;
  std::string name;
  VkPhysicalDeviceType type;
  uint32_t apiVersion;
  bool hasComputeQueue;
  const char* TypeName() const;
};

struct ContextOptions {
  bool validation = false;  // VK_LAYER_KHRONOS_validation with synchronization validation
  std::string device;       // "" = best; a number = that index; else a name substring
  bool verbose = false;
};

class Context {
 public:
  // Throws Error when there is no Vulkan loader, no device, or no device matches.
  explicit Context(const ContextOptions& options);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkDevice Device() const { return device_; }
  VkPhysicalDevice PhysicalDevice() const { return physical_; }
  VkQueue Queue() const { return queue_; }
  uint32_t QueueFamily() const { return queueFamily_; }
  const VkPhysicalDeviceProperties& Properties() const { return props_; }
  const VkPhysicalDeviceMemoryProperties& MemoryProperties() const { return memProps_; }
  std::string DeviceName() const { return props_.deviceName; }

  // The pipelines compiled on this device (pipeline_cache.h).
  PipelineCache& Pipelines() const { return *pipelines_; }

  // Validation messages (warnings + errors) reported so far; 0 without validation.
  uint32_t ValidationMessages() const { return validation_.Count(); }

  // Names an object for validation messages and debuggers (no-op without debug utils).
  void Name(VkObjectType type, uint64_t handle, const char* name) const;

  // Records and submits a one-off command buffer, waiting for it to finish.
  template <class F>
  void Submit(F&& record) const {
    VkCommandBuffer cb = BeginOneShot();
    record(cb);
    EndOneShot(cb);
  }

 private:
  void Destroy();
  VkCommandBuffer BeginOneShot() const;
  void EndOneShot(VkCommandBuffer cb) const;

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  VkPhysicalDeviceProperties props_{};
  VkPhysicalDeviceMemoryProperties memProps_{};
  PFN_vkSetDebugUtilsObjectNameEXT setName_ = nullptr;
  ValidationCounter validation_{"vkpt: validation"};
  std::unique_ptr<PipelineCache> pipelines_;
};

// Every physical device the loader reports (empty when there is none or no loader).
std::vector<DeviceInfo> ListDevices();

}  // namespace vkpt::internal::vk

// Mutants of vkpt's Vulkan teardown (keep_vulkan_objects.cpp): while one is on, every call
// of the test program that would free an object of its kind returns without freeing it,
// so the program keeps each one it made, as a renderer that leaked one a pass, a render or
// a frame would. The memory and validation tests must catch both.
#pragma once

namespace vkpt::internal::test {

enum class KeptObjects {
  None,
  Memory,           // vkFreeMemory: every buffer's memory
  DescriptorPools,  // vkDestroyDescriptorPool: every kernel's descriptor pool and its set
};

// Turns a mutant on for the scope of this object.
class KeepVulkanObjects {
 public:
  explicit KeepVulkanObjects(KeptObjects kind);
  ~KeepVulkanObjects();
  KeepVulkanObjects(const KeepVulkanObjects&) = delete;
  KeepVulkanObjects& operator=(const KeepVulkanObjects&) = delete;
};

}  // namespace vkpt::internal::test

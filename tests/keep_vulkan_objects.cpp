// The test program's own definitions of two Vulkan entry points: vkpt's code linked into
// it calls these, which call the loader's unless a mutant (keep_vulkan_objects.h) is on.
#include "keep_vulkan_objects.h"

#include <dlfcn.h>
#include <vulkan/vulkan.h>

#include <atomic>

namespace vkpt::internal::test {
namespace {

std::atomic<KeptObjects> gKept{KeptObjects::None};

// The loader's function of that name (the next definition after this program's).
template <class F>
F Loader(const char* name) {
  return reinterpret_cast<F>(dlsym(RTLD_NEXT, name));
}

}  // namespace

KeepVulkanObjects::KeepVulkanObjects(KeptObjects kind) { gKept = kind; }
KeepVulkanObjects::~KeepVulkanObjects() { gKept = KeptObjects::None; }

}  // namespace vkpt::internal::test

using vkpt::internal::test::KeptObjects;

extern "C" {

VKAPI_ATTR void VKAPI_CALL vkFreeMemory(VkDevice device, VkDeviceMemory memory, const VkAllocationCallbacks* a) {
  static const auto next = vkpt::internal::test::Loader<PFN_vkFreeMemory>("vkFreeMemory");
  if (vkpt::internal::test::gKept != KeptObjects::Memory) next(device, memory, a);
}

VKAPI_ATTR void VKAPI_CALL vkDestroyDescriptorPool(VkDevice device, VkDescriptorPool pool,
                                                   const VkAllocationCallbacks* a) {
  static const auto next = vkpt::internal::test::Loader<PFN_vkDestroyDescriptorPool>("vkDestroyDescriptorPool");
  if (vkpt::internal::test::gKept != KeptObjects::DescriptorPools) next(device, pool, a);
}

}  // extern "C"

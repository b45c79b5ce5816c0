#include "vk/context.h"

#include <algorithm>
#include <cstdio>

#include "util/error.h"
#include "vk/instance.h"
#include "vk/vk_check.h"

namespace vkpt::internal::vk {
namespace {

std::vector<VkPhysicalDevice> PhysicalDevices(VkInstance instance) {
  uint32_t n = 0;
  VKPT_VK_CHECK(vkEnumeratePhysicalDevices(instance, &n, nullptr));
  std::vector<VkPhysicalDevice> devices(n);
  VKPT_VK_CHECK(vkEnumeratePhysicalDevices(instance, &n, devices.data()));
  devices.resize(n);
  return devices;
}

std::optional<uint32_t> ComputeQueueFamily(VkPhysicalDevice d) {
  uint32_t n = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(d, &n, nullptr);
  std::vector<VkQueueFamilyProperties> families(n);
  vkGetPhysicalDeviceQueueFamilyProperties(d, &n, families.data());
  for (uint32_t i = 0; i < n; ++i)
    if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) return i;
  return std::nullopt;
}

DeviceInfo Describe(VkPhysicalDevice d, uint32_t index) {
  VkPhysicalDeviceProperties p;
  vkGetPhysicalDeviceProperties(d, &p);
  return {index, p.deviceName, p.deviceType, p.apiVersion, ComputeQueueFamily(d).has_value()};
}

int TypeRank(VkPhysicalDeviceType t) {
  switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
    default: return 4;
  }
}

// The index into `infos` of the device --device `want` names ("": the best with what vkpt
// needs, by type: discrete, integrated, virtual GPU, CPU); throws Error when none
// does, or the one named lacks a compute queue or Vulkan 1.2.
uint32_t ChooseDevice(const std::vector<DeviceInfo>& infos, const std::string& want) {
  std::optional<uint32_t> chosen;
  if (want.empty()) {
    for (const DeviceInfo& d : infos)
      if (d.hasComputeQueue && d.apiVersion >= VK_API_VERSION_1_2 &&
          (!chosen || TypeRank(d.type) < TypeRank(infos[*chosen].type)))
        chosen = d.index;
    if (!chosen) throw Error("no Vulkan 1.2 device with a compute queue; " + std::string(kNoDeviceFix));
  } else if (std::all_of(want.begin(), want.end(), ::isdigit)) {
    uint32_t i = uint32_t(std::stoul(want));
    if (i >= infos.size())
      throw Error("--device " + want + ": there are only " + std::to_string(infos.size()) +
                  " Vulkan device(s) (see --list-devices)");
    chosen = i;
  } else {
    for (const DeviceInfo& d : infos)
      if (d.name.find(want) != std::string::npos) {
        chosen = d.index;
        break;
      }
    if (!chosen) throw Error("--device \"" + want + "\" matches no Vulkan device (see --list-devices)");
  }
  const DeviceInfo& info = infos[*chosen];
  if (!info.hasComputeQueue) throw Error("Vulkan device \"" + info.name + "\" has no compute queue");
  if (info.apiVersion < VK_API_VERSION_1_2)
    throw Error("Vulkan device \"" + info.name + "\" does not support Vulkan 1.2");
  return *chosen;
}

// The physical device --device `want` names (see ChooseDevice).
VkPhysicalDevice PickDevice(VkInstance instance, const std::string& want) {
  std::vector<VkPhysicalDevice> devices = PhysicalDevices(instance);
  if (devices.empty()) throw Error(std::string("no Vulkan device found; ") + kNoDeviceFix);
  std::vector<DeviceInfo> infos;
  for (uint32_t i = 0; i < devices.size(); ++i) infos.push_back(Describe(devices[i], i));
  return devices[ChooseDevice(infos, want)];
}

// The pool of the one-shot command buffers (Submit), each reset as it is freed.
VkCommandPool CreateCommandPool(VkDevice device, uint32_t queueFamily) {
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  poolInfo.queueFamilyIndex = queueFamily;
  VkCommandPool pool = VK_NULL_HANDLE;
  VKPT_VK_CHECK(vkCreateCommandPool(device, &poolInfo, nullptr, &pool));
  return pool;
}

}  // namespace

const char* DeviceInfo::TypeName() const {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
    default: return "other";
  }
}

std::vector<DeviceInfo> ListDevices() {
  std::vector<DeviceInfo> out;
  try {
    VkInstance instance = CreateInstance(false, false, nullptr);
    std::vector<VkPhysicalDevice> devices;
    try {
      devices = PhysicalDevices(instance);
    } catch (...) {
      vkDestroyInstance(instance, nullptr);
      throw;
    }
    for (uint32_t i = 0; i < devices.size(); ++i) out.push_back(Describe(devices[i], i));
    vkDestroyInstance(instance, nullptr);
  } catch (const Error&) {
    out.clear();
  }
  return out;
}

Context::Context(const ContextOptions& options) {
  try {
    const bool debugUtils = CheckDebugUtils(options.validation);
    const VkDebugUtilsMessengerCreateInfoEXT messengerInfo = validation_.Info();
    instance_ = CreateInstance(options.validation, debugUtils, &messengerInfo);
    if (options.validation) messenger_ = CreateMessenger(instance_, messengerInfo);
    if (debugUtils)
      setName_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
          vkGetInstanceProcAddr(instance_, "vkSetDebugUtilsObjectNameEXT"));

    physical_ = PickDevice(instance_, options.device);
    queueFamily_ = *ComputeQueueFamily(physical_);
    vkGetPhysicalDeviceProperties(physical_, &props_);
    vkGetPhysicalDeviceMemoryProperties(physical_, &memProps_);
    device_ = CreateDevice(physical_, queueFamily_);
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
    pool_ = CreateCommandPool(device_, queueFamily_);
    pipelines_ = std::make_unique<PipelineCache>(device_);
  } catch (...) {
    Destroy();
    throw;
  }
}

Context::~Context() { Destroy(); }

void Context::Destroy() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    pipelines_.reset();
    if (pool_) vkDestroyCommandPool(device_, pool_, nullptr);
    vkDestroyDevice(device_, nullptr);
  }
  if (messenger_) DestroyMessenger(instance_, messenger_);
  if (instance_) vkDestroyInstance(instance_, nullptr);
  pool_ = VK_NULL_HANDLE;
  device_ = VK_NULL_HANDLE;
  messenger_ = VK_NULL_HANDLE;
  instance_ = VK_NULL_HANDLE;
}

void Context::Name(VkObjectType type, uint64_t handle, const char* name) const {
  if (!setName_) return;
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = name;
  setName_(device_, &info);
}

VkCommandBuffer Context::BeginOneShot() const {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cb;
  VKPT_VK_CHECK(vkAllocateCommandBuffers(device_, &alloc, &cb));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VkResult r = vkBeginCommandBuffer(cb, &begin);
  if (r != VK_SUCCESS) vkFreeCommandBuffers(device_, pool_, 1, &cb);
  VKPT_VK_CHECK(r);
  return cb;
}

void Context::EndOneShot(VkCommandBuffer cb) const {
  // Every step runs only if the previous one succeeded; cleanup happens either way and
  // the error names the call that failed.
  VkFence fence = VK_NULL_HANDLE;
  const char* call = "vkEndCommandBuffer";
  VkResult r = vkEndCommandBuffer(cb);
  if (r == VK_SUCCESS) {
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    call = "vkCreateFence";
    r = vkCreateFence(device_, &fenceInfo, nullptr, &fence);
  }
  if (r == VK_SUCCESS) {
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cb;
    call = "vkQueueSubmit";
    r = vkQueueSubmit(queue_, 1, &submit, fence);
  }
  if (r == VK_SUCCESS) {
    call = "vkWaitForFences";
    r = vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX);
  }
  if (fence) vkDestroyFence(device_, fence, nullptr);
  vkFreeCommandBuffers(device_, pool_, 1, &cb);
  Check(r, call);
}

}  // namespace vkpt::internal::vk

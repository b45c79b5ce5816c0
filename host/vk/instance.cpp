#include "vk/instance.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "util/error.h"
#include "vk/vk_check.h"

namespace vkpt::internal::vk {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool HasInstanceExtension(const char* name) {
  uint32_t n = 0;
  if (vkEnumerateInstanceExtensionProperties(nullptr, &n, nullptr) != VK_SUCCESS) return false;
  std::vector<VkExtensionProperties> exts(n);
  vkEnumerateInstanceExtensionProperties(nullptr, &n, exts.data());
  return std::any_of(exts.begin(), exts.end(), [&](const auto& e) { return std::strcmp(e.extensionName, name) == 0; });
}

bool HasLayer(const char* name) {
  uint32_t n = 0;
  if (vkEnumerateInstanceLayerProperties(&n, nullptr) != VK_SUCCESS) return false;
  std::vector<VkLayerProperties> layers(n);
  vkEnumerateInstanceLayerProperties(&n, layers.data());
  return std::any_of(layers.begin(), layers.end(), [&](const auto& l) { return std::strcmp(l.layerName, name) == 0; });
}

}  // namespace

bool CheckDebugUtils(bool validation) {
  if (validation && !HasLayer(kValidationLayer))
    throw Error(std::string("validation requested but ") + kValidationLayer +
                " is not installed (Debian: apt-get install vulkan-validationlayers)");
  const bool debugUtils = HasInstanceExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  if (validation && !debugUtils) throw Error("validation needs VK_EXT_debug_utils, which the loader lacks");
  return debugUtils;
}

VKAPI_ATTR VkBool32 VKAPI_CALL ValidationCounter::OnMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                            VkDebugUtilsMessageTypeFlagsEXT,
                                                            const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                            void* user) {
  auto* self = static_cast<ValidationCounter*>(user);
  const char* level = severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning";
  std::fprintf(stderr, "%s %s: %s\n", self->prefix_, level, data->pMessage);
  self->count_.fetch_add(1);
  return VK_FALSE;
}

VkDebugUtilsMessengerCreateInfoEXT ValidationCounter::Info() {
  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messengerInfo.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messengerInfo.pfnUserCallback = &ValidationCounter::OnMessage;
  messengerInfo.pUserData = this;
  return messengerInfo;
}

VkInstance CreateInstance(bool validation, bool debugUtils, const VkDebugUtilsMessengerCreateInfoEXT* messengerInfo,
                          std::span<const char* const> wanted) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "vkpt";
  app.pEngineName = "vkpt";
  app.apiVersion = VK_API_VERSION_1_2;
  std::vector<const char*> layers, extensions(wanted.begin(), wanted.end());
  if (debugUtils) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  // Synchronization validation is off by default in the layer; 1.3.239 predates
  // VK_EXT_layer_settings, so it is switched on through VkValidationFeaturesEXT.
  VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enables;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  if (validation) {
    layers.push_back(kValidationLayer);
    features.pNext = messengerInfo;  // also catches messages from instance creation
    info.pNext = &features;
  }
  info.enabledLayerCount = uint32_t(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = uint32_t(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkInstance instance = VK_NULL_HANDLE;
  VkResult r = vkCreateInstance(&info, nullptr, &instance);
  if (r == VK_ERROR_INCOMPATIBLE_DRIVER || r == VK_ERROR_INITIALIZATION_FAILED)
    throw Error(std::string("no Vulkan device found (vkCreateInstance: ") + ResultName(r) + "); " + kNoDeviceFix);
  if (r == VK_ERROR_EXTENSION_NOT_PRESENT) {
    std::string names;
    for (const char* e : wanted) names += (names.empty() ? "" : ", ") + std::string(e);
    throw Error("the Vulkan driver lacks an instance extension asked for (" + names + ")");
  }
  VKPT_VK_CHECK(r);
  return instance;
}

VkDevice CreateDevice(VkPhysicalDevice physical, uint32_t queueFamily, std::span<const char* const> extensions) {
  float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = queueFamily;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = uint32_t(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkDevice device = VK_NULL_HANDLE;
  VKPT_VK_CHECK(vkCreateDevice(physical, &info, nullptr, &device));
  return device;
}

VkDebugUtilsMessengerEXT CreateMessenger(VkInstance instance, const VkDebugUtilsMessengerCreateInfoEXT& info) {
  auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
  if (!create) throw Error("vkCreateDebugUtilsMessengerEXT is not available");
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VKPT_VK_CHECK(create(instance, &info, nullptr, &messenger));
  return messenger;
}

void DestroyMessenger(VkInstance instance, VkDebugUtilsMessengerEXT messenger) {
  auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
  if (destroy) destroy(instance, messenger, nullptr);
}

}  // namespace vkpt::internal::vk

// The Vulkan devices a scene can be rendered on (SceneSettings::device names one by index
// or name), described without Vulkan's types: for the library's Devices() and the command
// line's --list-devices.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vkpt::internal {

struct DeviceDescription {
  uint32_t index;
  std::string name;
  std::string type;  // "discrete GPU", "integrated GPU", "virtual GPU", "CPU" or "other"
  uint32_t apiMajor, apiMinor;
  bool compute;  // has a compute queue, which vkpt needs
};

// In index order; empty without a Vulkan loader or driver.
std::vector<DeviceDescription> DescribeDevices();

}  // namespace vkpt::internal

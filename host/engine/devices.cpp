#include "engine/devices.h"

#include "vk/context.h"

namespace vkpt::internal {

std::vector<DeviceDescription> DescribeDevices() {
  std::vector<DeviceDescription> out;
  for (const vk::DeviceInfo& d : vk::ListDevices())
    out.push_back({d.index, d.name, d.TypeName(), VK_API_VERSION_MAJOR(d.apiVersion),
                   VK_API_VERSION_MINOR(d.apiVersion), d.hasComputeQueue});
  return out;
}

}  // namespace vkpt::internal

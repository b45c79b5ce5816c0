#include "vkpt/setting_choices.h"

namespace vkpt::internal {

const Choices<vkpt::Backend>& BackendChoices() {
  static const Choices<vkpt::Backend> choices = {
      {"auto", vkpt::Backend::Auto}, {"cpu", vkpt::Backend::Cpu}, {"vulkan", vkpt::Backend::Vulkan}};
  return choices;
}

const Choices<vkpt::LightSampler>& LightSamplerChoices() {
  static const Choices<vkpt::LightSampler> choices = {
      {"auto", vkpt::LightSampler::Auto}, {"power", vkpt::LightSampler::Power}, {"tree", vkpt::LightSampler::Tree}};
  return choices;
}

std::string OrList(const std::vector<std::string>& names) {
  std::string list;
  for (size_t k = 0; k < names.size(); ++k) list += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + names[k];
  return list;
}

}  // namespace vkpt::internal

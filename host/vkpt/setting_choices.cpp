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

std::string QuotedNames(const std::vector<std::string>& names) {
  std::string text;
  for (size_t i = 0; i < names.size(); ++i)
    text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + ("\"" + names[i] + "\"");
  return text;
}

}  // namespace vkpt::internal

// The names of the choice settings' values, each written once: the command line's
// --backend and --light-sampler and Python's backend= and light_sampler= read them here.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "vkpt/settings_schema.h"

namespace vkpt::internal {

template <class E>
using Choices = std::vector<std::pair<std::string, E>>;

const Choices<vkpt::Backend>& BackendChoices();            // auto, cpu, vulkan
const Choices<vkpt::LightSampler>& LightSamplerChoices();  // auto, power, tree

// "a, b or c": how a message lists the values a setting takes.
std::string OrList(const std::vector<std::string>& names);

// The value named `name` among `choices` of the setting `key`, else a SettingError in
// Python's terms: backend must be "auto", "cpu" or "vulkan", got "gpu".
template <class E>
E Chosen(const std::string& key, const Choices<E>& choices, const std::string& name) {
  std::vector<std::string> names;
  for (const auto& [n, value] : choices) {
    if (n == name) return value;
    names.push_back("\"" + n + "\"");
  }
  throw SettingError(key + " must be " + OrList(names) + ", got \"" + name + "\"");
}

// The name of `value` among `choices` (every value has one).
template <class E>
const std::string& ChoiceName(const Choices<E>& choices, E value) {
  for (const auto& [name, v] : choices)
    if (v == value) return name;
  throw std::logic_error("a choice without a name");
}

}  // namespace vkpt::internal

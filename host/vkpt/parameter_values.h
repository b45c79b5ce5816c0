// A scene parameter's value (vkpt::ParameterValue) read into the engine's types: its kind
// checked, its range where it has one, each refusal a SettingError naming the key.
#pragma once

#include <string>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "vkpt/public_values.h"
#include "vkpt/settings_schema.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal {

// "a number", "a switch", "3 numbers", "4 numbers (x, y, z, w)" or "a name".
const char* KindOf(const vkpt::ParameterValue& v);

template <class T>
vkpt::ParameterValue ParameterOf(T v) {
  return vkpt::ParameterValue(Public(v));
}
inline vkpt::ParameterValue ParameterOf(double v) { return v; }

// The value as `Want`; SettingError if it is of another kind.
template <class Want>
const Want& Expect(const vkpt::ParameterValue& v, const std::string& key) {
  const Want* want = std::get_if<Want>(&v);
  if (!want) throw SettingError(key + " takes " + KindOf(Want{}) + ", not " + KindOf(v));
  return *want;
}

// `v` within `range`, else SettingError naming `name`.
float Checked(double v, const Range& range, const std::string& name);

// `field` set to `v`, checked against `range` (a bool: none; a vector: each component).
void Assign(float& field, const vkpt::ParameterValue& v, const Range& range, const std::string& key);
void Assign(bool& field, const vkpt::ParameterValue& v, const Range& range, const std::string& key);
void Assign(glm::vec3& field, const vkpt::ParameterValue& v, const Range& range, const std::string& key);

}  // namespace vkpt::internal

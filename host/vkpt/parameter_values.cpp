#include "vkpt/parameter_values.h"

namespace vkpt::internal {

const char* KindOf(const vkpt::ParameterValue& v) {
  switch (v.index()) {
    case 0: return "a number";
    case 1: return "a switch";
    case 2: return "3 numbers";
    case 3: return "4 numbers (x, y, z, w)";
    default: return "a name";
  }
}

float Checked(double v, const Range& range, const std::string& name) {
  if (!range.Holds(v)) throw SettingError(OutOfRange(name, range, v, FormatNumber(v)));
  return float(v);
}

void Assign(float& field, const vkpt::ParameterValue& v, const Range& range, const std::string& key) {
  field = Checked(Expect<double>(v, key), range, key);
}

void Assign(bool& field, const vkpt::ParameterValue& v, const Range&, const std::string& key) {
  field = Expect<bool>(v, key);
}

void Assign(glm::vec3& field, const vkpt::ParameterValue& v, const Range& range, const std::string& key) {
  const vkpt::Rgb& rgb = Expect<vkpt::Rgb>(v, key);
  field = glm::vec3(Checked(rgb[0], range, key + "[0]"), Checked(rgb[1], range, key + "[1]"),
                    Checked(rgb[2], range, key + "[2]"));
}

}  // namespace vkpt::internal

#include "vkpt/scene_parameters.h"

#include <map>
#include <string>
#include <utility>

#include "util/error.h"
#include "vkpt/client.h"
#include "vkpt/scene_access.h"
#include "vkpt/settings_schema.h"

namespace vkpt::internal {
namespace {

const char kMaterials[] = "materials/";
const char kEnvironmentIntensity[] = "environment/intensity";

vkpt::ParameterValue ValueOf(float v) { return double(v); }
vkpt::ParameterValue ValueOf(bool v) { return v; }
vkpt::ParameterValue ValueOf(glm::vec3 v) { return vkpt::Rgb{v.x, v.y, v.z}; }

const char* KindOf(const vkpt::ParameterValue& v) {
  return std::holds_alternative<double>(v) ? "a number"
         : std::holds_alternative<bool>(v) ? "a switch"
                                           : "an RGB triple";
}

template <class Want>
const Want& Expect(const vkpt::ParameterValue& v, const std::string& key) {
  const Want* want = std::get_if<Want>(&v);
  if (!want) {
    const vkpt::ParameterValue kind = Want{};
    throw SettingError(key + " takes " + KindOf(kind) + ", not " + KindOf(v));
  }
  return *want;
}

float Checked(double v, const Range& range, const std::string& name) {
  if (!range.Holds(v)) throw SettingError(OutOfRange(name, range, v, FormatNumber(v)));
  return float(v);
}

// `field` set to `v`, checked against `range` (a bool: none).
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

// One editable field of a material, from VKPT_MATERIAL_FACTORS.
struct MaterialField {
  const char* name;
  vkpt::ParameterValue (*get)(const Material&);
  void (*set)(Material&, const vkpt::ParameterValue&, const std::string& key);
};

#define VKPT_MATERIAL_FIELD(type, member, python, lo, hi, doc)              \
  {python, [](const Material& m) { return ValueOf(m.member); },             \
   [](Material& m, const vkpt::ParameterValue& v, const std::string& key) { \
     Assign(m.member, v, Range{lo, hi}, key);                               \
   }},
const MaterialField kMaterialFields[] = {VKPT_MATERIAL_FACTORS(VKPT_MATERIAL_FIELD)};
#undef VKPT_MATERIAL_FIELD

[[noreturn]] void Unknown(const std::string& key, const LoadedScene& loaded) {
  std::string fields;
  for (const MaterialField& f : kMaterialFields) fields += std::string(fields.empty() ? "" : ", ") + f.name;
  std::string keys = "materials/<0 to " + std::to_string(loaded.scene().materials.size() - 1) + ">/<" + fields + ">";
  if (loaded.HasEnvironmentMap()) keys += " and " + std::string(kEnvironmentIntensity);
  const std::string shown = key.size() > 80 ? key.substr(0, 80) + "…" : key;
  throw SettingError("no scene parameter \"" + shown + "\": the keys are " + keys);
}

// "materials/<i>/<field>" as the material's index and its field; Unknown if it is not one.
std::pair<uint32_t, const MaterialField*> MaterialKey(const std::string& key, const LoadedScene& loaded) {
  const size_t slash = key.find('/', sizeof kMaterials - 1);
  const std::string index = key.substr(sizeof kMaterials - 1, slash - (sizeof kMaterials - 1));
  if (slash == std::string::npos || index.empty() || index.size() > 9 || (index.size() > 1 && index[0] == '0') ||
      index.find_first_not_of("0123456789") != std::string::npos)
    Unknown(key, loaded);
  const uint32_t i = uint32_t(std::stoul(index));
  if (i >= loaded.scene().materials.size()) Unknown(key, loaded);
  for (const MaterialField& f : kMaterialFields)
    if (key.compare(slash + 1, std::string::npos, f.name) == 0) return {i, &f};
  Unknown(key, loaded);
}

}  // namespace

vkpt::ParameterMap ParametersOf(const LoadedScene& loaded) {
  vkpt::ParameterMap p;
  const std::vector<Material>& materials = loaded.scene().materials;
  for (size_t i = 0; i < materials.size(); ++i)
    for (const MaterialField& f : kMaterialFields)
      p[kMaterials + std::to_string(i) + "/" + f.name] = f.get(materials[i]);
  if (loaded.HasEnvironmentMap()) p[kEnvironmentIntensity] = double(loaded.Settings().envIntensity);
  return p;
}

void ApplyParameters(LoadedScene& loaded, const vkpt::ParameterMap& changes) {
  std::map<uint32_t, Material> edited;  // the materials changed, as they will be
  float intensity = loaded.Settings().envIntensity;
  for (const auto& [key, value] : changes) {
    if (key == kEnvironmentIntensity && loaded.HasEnvironmentMap()) {
      const Setting& s = SettingOf("environment_intensity");
      intensity = Checked(Expect<double>(value, key), *s.range, key);
    } else if (key.rfind(kMaterials, 0) == 0) {
      const auto [index, field] = MaterialKey(key, loaded);
      auto [it, added] = edited.try_emplace(index, loaded.scene().materials[index]);
      field->set(it->second, value, key);
    } else {
      Unknown(key, loaded);
    }
  }
  for (const auto& [index, material] : edited)
    for (const MaterialField& f : kMaterialFields)
      if (f.get(material) != f.get(loaded.scene().materials[index])) {
        loaded.SetMaterial(index, material);
        break;
      }
  if (intensity != loaded.Settings().envIntensity) loaded.SetEnvironmentIntensity(intensity);
}

}  // namespace vkpt::internal

namespace vkpt {

ParameterMap Scene::Parameters() const { return internal::ParametersOf(SceneAccess::Engine(*this)); }

void Scene::Update(const ParameterMap& changes) {
  internal::Translated([&] { internal::ApplyParameters(SceneAccess::Engine(*this), changes); });
}

}  // namespace vkpt

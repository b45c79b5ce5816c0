#include "vkpt/scene_parameters.h"

#include <map>
#include <string>
#include <utility>

#include "util/error.h"
#include "vkpt/client.h"
#include "vkpt/parameter_values.h"
#include "vkpt/scene_access.h"

namespace vkpt::internal {
namespace {

const char kMaterials[] = "materials/", kNodes[] = "nodes/", kLights[] = "lights/";
const char kEnvironmentIntensity[] = "environment/intensity";

// One editable field of a material, from VKPT_MATERIAL_FACTORS.
struct MaterialField {
  const char* name;
  vkpt::ParameterValue (*get)(const Material&);
  void (*set)(Material&, const vkpt::ParameterValue&, const std::string& key);
};

#define VKPT_MATERIAL_FIELD(type, member, python, lo, hi, doc)              \
  {python, [](const Material& m) { return ParameterOf(m.member); },         \
   [](Material& m, const vkpt::ParameterValue& v, const std::string& key) { \
     Assign(m.member, v, Range{lo, hi}, key);                               \
   }},
const MaterialField kMaterialFields[] = {VKPT_MATERIAL_FACTORS(VKPT_MATERIAL_FIELD)};
#undef VKPT_MATERIAL_FIELD

// A node's and a light's fields. Their values are checked by the rules that check a file
// (GltfAsset::Edit): a node's numbers finite and its rotation one that can be made unit, a
// light's colour in [0, 1] and its intensity finite and >= 0.
struct NodeField {
  const char* name;
  vkpt::ParameterValue (*get)(const NodeSummary&);
  void (*set)(NodeEdit&, const vkpt::ParameterValue&, const std::string& key);
};
const NodeField kNodeFields[] = {
    {"translation", [](const NodeSummary& n) { return ParameterOf(n.translation); },
     [](NodeEdit& e, const vkpt::ParameterValue& v, const std::string& key) {
       const vkpt::Vec3& t = Expect<vkpt::Vec3>(v, key);
       e.translation = glm::dvec3(t[0], t[1], t[2]);
     }},
    {"rotation", [](const NodeSummary& n) { return ParameterOf(n.rotation); },
     [](NodeEdit& e, const vkpt::ParameterValue& v, const std::string& key) {
       const vkpt::Quat& q = Expect<vkpt::Quat>(v, key);
       e.rotation = glm::dquat(q[3], q[0], q[1], q[2]);  // (w, x, y, z)
     }},
    {"scale", [](const NodeSummary& n) { return ParameterOf(n.scale); },
     [](NodeEdit& e, const vkpt::ParameterValue& v, const std::string& key) {
       const vkpt::Vec3& s = Expect<vkpt::Vec3>(v, key);
       e.scale = glm::dvec3(s[0], s[1], s[2]);
     }},
};

struct LightField {
  const char* name;
  vkpt::ParameterValue (*get)(const LightSource&);
  void (*set)(LightEdit&, const vkpt::ParameterValue&, const std::string& key);
};
const LightField kLightFields[] = {
    {"color", [](const LightSource& l) { return ParameterOf(l.color); },
     [](LightEdit& e, const vkpt::ParameterValue& v, const std::string& key) {
       const vkpt::Rgb& c = Expect<vkpt::Rgb>(v, key);
       e.color = glm::dvec3(c[0], c[1], c[2]);
     }},
    {"intensity", [](const LightSource& l) { return ParameterOf(l.intensity); },
     [](LightEdit& e, const vkpt::ParameterValue& v, const std::string& key) { e.intensity = Expect<double>(v, key); }},
};

// "<group><i>/<field>" for every item i and every field of `fields`.
template <class Field, size_t N, class Item>
void List(vkpt::ParameterMap& p, const char* group, const std::vector<Item>& items, const Field (&fields)[N]) {
  for (size_t i = 0; i < items.size(); ++i)
    for (const Field& f : fields) p[group + std::to_string(i) + "/" + f.name] = f.get(items[i]);
}

// "<group>/<0 to n-1>/<field, field, …>", or "" for n = 0.
template <class Field, size_t N>
std::string KeyShape(const char* group, size_t n, const Field (&fields)[N]) {
  if (n == 0) return "";
  std::string names;
  for (const Field& f : fields) names += std::string(names.empty() ? "" : ", ") + f.name;
  return group + std::string("<0 to ") + std::to_string(n - 1) + ">/<" + names + ">";
}

[[noreturn]] void Unknown(const std::string& key, const LoadedScene& loaded) {
  std::vector<std::string> shapes = {KeyShape(kMaterials, loaded.scene().materials.size(), kMaterialFields),
                                     KeyShape(kNodes, loaded.Asset().Nodes().size(), kNodeFields),
                                     KeyShape(kLights, loaded.Asset().Lights().size(), kLightFields)};
  if (loaded.HasEnvironmentMap()) shapes.push_back(kEnvironmentIntensity);
  std::string keys;
  for (const std::string& s : shapes)
    if (!s.empty()) keys += (keys.empty() ? "" : "; ") + s;
  const std::string shown = key.size() > 80 ? key.substr(0, 80) + "…" : key;
  throw SettingError("no scene parameter \"" + shown + "\": the keys are " + keys);
}

// A key of Parameters() in `group` as its index and the field's name after it.
std::pair<uint32_t, std::string> Split(const std::string& key, const char* group) {
  const size_t start = std::char_traits<char>::length(group), slash = key.find('/', start);
  return {uint32_t(std::stoul(key.substr(start, slash - start))), key.substr(slash + 1)};
}

template <class Field, size_t N>
const Field& FieldNamed(const std::string& name, const Field (&fields)[N]) {
  for (const Field& f : fields)
    if (name == f.name) return f;
  throw std::logic_error("no field " + name);
}

// What an update changes, every value checked.
struct Changes {
  std::map<uint32_t, Material> materials;  // the materials edited, as they will be
  AssetEdits asset;
  std::optional<float> environmentIntensity;
};

void Add(Changes& c, const LoadedScene& loaded, const std::string& key, const vkpt::ParameterValue& value) {
  if (key == kEnvironmentIntensity) {
    c.environmentIntensity = Checked(Expect<double>(value, key), *SettingOf("environment_intensity").range, key);
  } else if (key.rfind(kMaterials, 0) == 0) {
    const auto [i, field] = Split(key, kMaterials);
    auto [it, added] = c.materials.try_emplace(i, loaded.scene().materials[i]);
    FieldNamed(field, kMaterialFields).set(it->second, value, key);
  } else if (key.rfind(kNodes, 0) == 0) {
    const auto [i, field] = Split(key, kNodes);
    FieldNamed(field, kNodeFields).set(c.asset.nodes[i], value, key);
  } else {
    const auto [i, field] = Split(key, kLights);
    FieldNamed(field, kLightFields).set(c.asset.lights[i], value, key);
  }
}

}  // namespace

vkpt::ParameterMap ParametersOf(const LoadedScene& loaded) {
  vkpt::ParameterMap p;
  List(p, kMaterials, loaded.scene().materials, kMaterialFields);
  List(p, kNodes, loaded.Asset().Nodes(), kNodeFields);
  List(p, kLights, loaded.Asset().Lights(), kLightFields);
  if (loaded.HasEnvironmentMap()) p[kEnvironmentIntensity] = double(loaded.Settings().envIntensity);
  return p;
}

void ApplyParameters(LoadedScene& loaded, const vkpt::ParameterMap& changes) {
  const vkpt::ParameterMap now = ParametersOf(loaded);
  Changes c;
  for (const auto& [key, value] : changes) {
    const auto it = now.find(key);
    if (it == now.end()) Unknown(key, loaded);
    if (value.index() != it->second.index())
      throw SettingError(key + " takes " + KindOf(it->second) + ", not " + KindOf(value));
    if (value != it->second) Add(c, loaded, key, value);
  }
  for (const auto& [index, material] : c.materials)
    if (!IorHolds(material.ior))
      throw SettingError(kMaterials + std::to_string(index) + "/ior is " + FormatNumber(material.ior) +
                         ": it must be 0 or in [1, 1e6] (KHR_materials_ior)");
  // The file's rules, last: a refused edit leaves the scene as it was.
  if (!c.asset.Empty()) {
    try {
      loaded.Edit(c.asset);
    } catch (const Error& e) {
      throw SettingError(std::string("refused: ") + e.what());
    }
  }
  for (const auto& [index, material] : c.materials) loaded.SetMaterial(index, material);
  if (c.environmentIntensity) loaded.SetEnvironmentIntensity(*c.environmentIntensity);
}

}  // namespace vkpt::internal

namespace vkpt {

ParameterMap Scene::Parameters() const { return internal::ParametersOf(SceneAccess::Engine(*this)); }

void Scene::Update(const ParameterMap& changes) {
  internal::Translated([&] { internal::ApplyParameters(SceneAccess::Engine(*this), changes); });
}

}  // namespace vkpt

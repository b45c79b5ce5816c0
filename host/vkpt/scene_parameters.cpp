#include "vkpt/scene_parameters.h"

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "util/error.h"
#include "vkpt/client.h"
#include "vkpt/parameter_values.h"
#include "vkpt/scene_access.h"

namespace vkpt::internal {
namespace {

const char kMaterials[] = "materials/", kNodes[] = "nodes/", kLights[] = "lights/";
const char kEnvironmentIntensity[] = "environment/intensity", kEnvironmentRotation[] = "environment/rotation";
const char kVariant[] = "variant", kAnimation[] = "animation", kTime[] = "time";

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

// The one-of-a-kind keys the scene has: the choices where the file offers some, the
// environment's where it has a map.
std::vector<std::string> SingleKeys(const LoadedScene& loaded) {
  std::vector<std::string> keys;
  if (!loaded.scene().materialVariants.empty()) keys.push_back(kVariant);
  if (!loaded.scene().animations.empty()) keys.insert(keys.end(), {kAnimation, kTime});
  if (loaded.HasEnvironmentMap()) keys.insert(keys.end(), {kEnvironmentIntensity, kEnvironmentRotation});
  return keys;
}

[[noreturn]] void Unknown(const std::string& key, const LoadedScene& loaded) {
  std::vector<std::string> shapes = {KeyShape(kMaterials, loaded.scene().materials.size(), kMaterialFields),
                                     KeyShape(kNodes, loaded.Asset().Nodes().size(), kNodeFields),
                                     KeyShape(kLights, loaded.Asset().Lights().size(), kLightFields)};
  for (const std::string& k : SingleKeys(loaded)) shapes.push_back(k);
  std::string keys;
  for (const std::string& s : shapes)
    if (!s.empty()) keys += (keys.empty() ? "" : "; ") + s;
  const std::string shown = key.size() > 80 ? key.substr(0, 80) + "…" : key;
  throw SettingError("no scene parameter \"" + shown + "\": the keys are " + keys);
}

// How Parameters() spells the choice of `index` among `names`: its name where that names
// it, else its decimal index; "" for none (−1).
std::string Spelling(const std::vector<std::string>& names, int index) {
  if (index < 0) return "";
  const auto first = std::find(names.begin(), names.end(), names[index]);
  return !names[index].empty() && first - names.begin() == index ? names[index] : std::to_string(index);
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
  AssetEdits asset;
  std::optional<double> time;
  std::optional<float> environmentIntensity, environmentRotation;
};

void Add(Changes& c, const LoadedScene& loaded, const std::string& key, const vkpt::ParameterValue& value) {
  if (key == kEnvironmentIntensity) {
    c.environmentIntensity = Checked(Expect<double>(value, key), *SettingOf("environment_intensity").range, key);
  } else if (key == kEnvironmentRotation) {
    c.environmentRotation = Checked(Expect<double>(value, key), *SettingOf("environment_rotation").range, key);
  } else if (key == kVariant) {
    c.asset.variant = Expect<std::string>(value, key);
  } else if (key == kAnimation) {
    c.asset.animation = Expect<std::string>(value, key);
  } else if (key == kTime) {
    const double t = Expect<double>(value, key);
    const Range& range = *SettingOf("time").range;
    if (!range.Holds(t)) throw SettingError(OutOfRange(key, range, t, FormatNumber(t)));
    c.time = t;
  } else if (key.rfind(kMaterials, 0) == 0) {
    const auto [i, field] = Split(key, kMaterials);
    auto [it, added] = c.asset.materials.try_emplace(i, loaded.scene().materials[i]);
    FieldNamed(field, kMaterialFields).set(it->second, value, key);
  } else if (key.rfind(kNodes, 0) == 0) {
    const auto [i, field] = Split(key, kNodes);
    FieldNamed(field, kNodeFields).set(c.asset.nodes[i], value, key);
  } else {
    const auto [i, field] = Split(key, kLights);
    FieldNamed(field, kLightFields).set(c.asset.lights[i], value, key);
  }
}

// The rules between values: each material's ior, and a time only with an animation.
void CheckTogether(const Changes& c, const LoadedScene& loaded) {
  for (const auto& [index, material] : c.asset.materials)
    if (!IorHolds(material.ior))
      throw SettingError(kMaterials + std::to_string(index) + "/ior is " + FormatNumber(material.ior) +
                         ": it must be 0 or in [1, 1e6] (KHR_materials_ior)");
  const bool animated = c.asset.animation ? !c.asset.animation->empty() : loaded.scene().animation >= 0;
  const double time = c.time.value_or(loaded.Settings().choice.time);
  if (TimeWithoutAnimation(time, animated))
    throw SettingError(std::string(kTime) + " is " + FormatNumber(time) + " but no animation is chosen: set \"" +
                       kAnimation + "\" as well, or time to 0");
}

}  // namespace

vkpt::ParameterMap ParametersOf(const LoadedScene& loaded) {
  vkpt::ParameterMap p;
  List(p, kMaterials, loaded.scene().materials, kMaterialFields);
  List(p, kNodes, loaded.Asset().Nodes(), kNodeFields);
  List(p, kLights, loaded.Asset().Lights(), kLightFields);
  const Scene& scene = loaded.scene();
  if (!scene.materialVariants.empty()) p[kVariant] = Spelling(scene.materialVariants, scene.variant);
  if (!scene.animations.empty()) {
    p[kAnimation] = Spelling(Names(scene.animations), scene.animation);
    p[kTime] = loaded.Settings().choice.time;
  }
  if (loaded.HasEnvironmentMap()) {
    p[kEnvironmentIntensity] = double(loaded.Settings().envIntensity);
    p[kEnvironmentRotation] = double(loaded.Settings().envRotation);
  }
  return p;
}

ChosenSpellings ChoicesOf(const LoadedScene& loaded) {
  const Scene& scene = loaded.scene();
  return {Spelling(scene.materialVariants, scene.variant), Spelling(Names(scene.animations), scene.animation)};
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
  CheckTogether(c, loaded);
  // The file's rules, last: a refused edit leaves the scene as it was.
  if (!c.asset.Empty() || c.time) {
    try {
      loaded.Edit(c.asset, c.time.value_or(loaded.Settings().choice.time));
    } catch (const Error& e) {
      throw SettingError(std::string("refused: ") + e.what());
    }
  }
  if (c.environmentIntensity || c.environmentRotation)
    loaded.SetEnvironment(c.environmentIntensity.value_or(loaded.Settings().envIntensity),
                          c.environmentRotation.value_or(loaded.Settings().envRotation));
}

}  // namespace vkpt::internal

namespace vkpt {

ParameterMap Scene::Parameters() const { return internal::ParametersOf(SceneAccess::Engine(*this)); }

void Scene::Update(const ParameterMap& changes) {
  internal::Translated([&] {
    internal::ApplyParameters(SceneAccess::Engine(*this), changes);
    SceneAccess::EndProgressive(*this);
    // Each render's settings are checked against the choices made now.
    const internal::ChosenSpellings chosen = internal::ChoicesOf(SceneAccess::Engine(*this));
    SceneAccess::Options(*this).variant = chosen.variant;
    SceneAccess::Options(*this).animation = chosen.animation;
  });
}

}  // namespace vkpt

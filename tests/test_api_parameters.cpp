// Scene::Parameters() and Scene::Update(): an edit renders what a fresh load of the file
// so edited renders, bit for bit, on both backends; a refused edit changes nothing; an
// update that changes no value builds nothing again.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "api_test_util.h"
#include "test_util.h"
#include "vkpt/scene_access.h"

#include "vkpt/vkpt.h"

namespace vkpt::internal {
namespace {

using nlohmann::json;

const std::string kCornell = test::Cornell();

vkpt::Scene Open(const std::string& path, vkpt::Backend backend, const std::string& environment = "") {
  vkpt::SceneOptions options;
  options.backend = backend;
  options.environment = environment;
  return vkpt::Scene(path, options);
}

// The Cornell box edited by `edit`, written to `name` in `folder` beside a copy of its
// buffer.
std::string WriteCornell(const test::TempFolder& folder, const std::string& name,
                         const std::function<void(json&)>& edit) {
  std::ifstream in(kCornell);
  json file = json::parse(in);
  edit(file);
  if (!std::filesystem::exists(folder / "cornell.bin"))
    std::filesystem::copy_file(test::SourcePath("scenes/cornell.bin"), folder / "cornell.bin");
  std::ofstream(folder / name) << file.dump();
  return folder / name;
}

// A point light above the boxes (node 9), with `color` and `intensity`.
void AddPointLight(json& file, const json& color, double intensity) {
  file["extensionsUsed"].push_back("KHR_lights_punctual");
  file["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "point"}, {"color", color}, {"intensity", intensity}}};
  file["nodes"].push_back(
      {{"name", "bulb"}, {"translation", {278, 400, 280}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  file["scenes"][0]["nodes"].push_back(9);
}

// The Cornell box with its first material red and rough and its second metallic, its
// light twice as strong, its tall box turned, moved and squashed (every number one a
// float holds exactly), and a point light.
void EditCornell(json& file) {
  json& pbr0 = file["materials"][0]["pbrMetallicRoughness"];
  pbr0["baseColorFactor"] = {0.9, 0.1, 0.1, 1.0};
  pbr0["roughnessFactor"] = 0.35;
  file["materials"][1]["pbrMetallicRoughness"]["metallicFactor"] = 0.8;
  json& light = file["materials"][3];
  light["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] =
      2.0 * light["extensions"]["KHR_materials_emissive_strength"].value("emissiveStrength", 1.0);
  json& tallBox = file["nodes"][7];
  tallBox["rotation"] = {0.0, 1.0, 0.0, 0.0};
  tallBox["translation"] = {556.0, 0.0, 560.0};
  tallBox["scale"] = {1.0, 0.75, 1.0};
  AddPointLight(file, {1.0, 0.5, 0.25}, 60000.0);
}

uint32_t Builds(vkpt::Scene& scene) { return vkpt::SceneAccess::Engine(scene).Counts().builds; }

TEST(ApiParameters, AnEditRendersAsTheEditedFile) {
  const test::TempFolder folder("api-parameters");
  const std::string base = WriteCornell(folder, "base.gltf", [](json& f) { AddPointLight(f, {1, 1, 1}, 30000.0); });
  const std::string edited = WriteCornell(folder, "edited.gltf", EditCornell);
  for (vkpt::Backend backend : {vkpt::Backend::Cpu, vkpt::Backend::Vulkan}) {
    vkpt::Scene fresh = Open(edited, backend);
    vkpt::Scene live = Open(base, backend);
    const vkpt::RenderResult before = live.Render({}, test::SmallRender(3));  // built and uploaded before the edit
    live.Update(fresh.Parameters());
    EXPECT_EQ(live.Parameters(), fresh.Parameters());
    const vkpt::RenderResult after = live.Render({}, test::SmallRender(3));
    EXPECT_EQ(after.image.data, fresh.Render({}, test::SmallRender(3)).image.data) << after.engine;
    EXPECT_NE(after.image.data, before.image.data);
    EXPECT_EQ(Builds(live), 2u);
  }
}

// Each of `refused` raises SettingError with its message, and leaves the scene's values,
// its render and its built arrays as they were.
void ExpectEachRefused(vkpt::Scene& scene, const std::vector<std::pair<vkpt::ParameterMap, std::string>>& refused) {
  const vkpt::ParameterMap original = scene.Parameters();
  const vkpt::RenderResult before = scene.Render({}, test::SmallRender(3));
  for (const auto& [changes, message] : refused) {
    try {
      scene.Update(changes);
      ADD_FAILURE() << "accepted: " << message;
    } catch (const vkpt::SettingError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(scene.Parameters(), original);
  EXPECT_EQ(scene.Render({}, test::SmallRender(3)).image.data, before.image.data);
  EXPECT_EQ(Builds(scene), 1u);
}

TEST(ApiParameters, ARefusedEditChangesNothing) {
  vkpt::Scene scene = Open(kCornell, vkpt::Backend::Cpu);
  const std::vector<std::pair<vkpt::ParameterMap, std::string>> refused = {
      {{{"materials/0/roughness", 0.5}, {"materials/1/roughness", 1.5}}, "materials/1/roughness must be in [0, 1]"},
      {{{"materials/0/base_color", vkpt::Rgb{0.5f, -0.1f, 0.5f}}}, "materials/0/base_color[1] must be in [0, 1]"},
      {{{"materials/0/roughness", vkpt::Rgb{}}}, "takes a number, not 3 numbers"},
      {{{"materials/0/unlit", 1.0}}, "takes a switch, not a number"},
      {{{"materials/99/roughness", 0.5}}, "no scene parameter \"materials/99/roughness\""},
      {{{"materials/0/shininess", 0.5}}, "materials/<0 to 4>/<base_color, alpha"},
      {{{"materials/x/roughness", 0.5}}, "no scene parameter"},
      {{{"materials/00/roughness", 0.5}}, "no scene parameter \"materials/00/roughness\""},
      {{{std::string(1000, 'x'), 0.5}}, "no scene parameter \"" + std::string(80, 'x') + "…\": the keys"},
      {{{"environment/intensity", 2.0}}, "no scene parameter"},  // no environment map
      {{{"materials/0/ior", std::nan("")}}, "materials/0/ior must be in [0, 1e+06], got nan"},
      {{{"materials/0/ior", 0.5}}, "materials/0/ior is 0.5: it must be 0 or in [1, 1e6]"},
      {{{"materials/0/roughness", 0.5}, {"nodes/7/rotation", vkpt::Quat{0, 0, 0, 0}}},
       "refused: " + kCornell + ": nodes[7].rotation is not a unit quaternion"},
      {{{"nodes/7/translation", vkpt::Vec3{0, INFINITY, 0}}}, "nodes[7].translation has a non-finite value"},
      {{{"nodes/7/scale", 2.0}}, "nodes/7/scale takes 3 numbers, not a number"},
      {{{"nodes/7/rotation", vkpt::Vec3{}}}, "nodes/7/rotation takes 4 numbers (x, y, z, w), not 3 numbers"},
      {{{"nodes/9/scale", vkpt::Vec3{}}}, "nodes/<0 to 8>/<translation, rotation, scale>"},
      {{{"lights/0/color", vkpt::Vec3{}}}, "no scene parameter \"lights/0/color\""},  // no lights
  };
  ExpectEachRefused(scene, refused);
}

// A light's values are checked as the file's are, and so is the pose they make: a light's
// node scaled to nothing leaves it no direction.
TEST(ApiParameters, ARefusedLightEditChangesNothing) {
  const test::TempFolder folder("api-parameters-light");
  const std::string base = WriteCornell(folder, "base.gltf", [](json& f) { AddPointLight(f, {1, 1, 1}, 30000.0); });
  vkpt::Scene scene = Open(base, vkpt::Backend::Cpu);
  const std::vector<std::pair<vkpt::ParameterMap, std::string>> refused = {
      {{{"lights/0/intensity", -1.0}}, "lights[0].intensity must be a finite number >= 0"},
      {{{"lights/0/color", vkpt::Rgb{1.0f, 1.5f, 1.0f}}}, "lights[0].color has 1.5"},
      {{{"lights/0/intensity", 2.0}, {"nodes/9/scale", vkpt::Vec3{0, 0, 0}}},
       "nodes[9]: the transform of its light (lights[0]) is degenerate"},
  };
  ExpectEachRefused(scene, refused);
}

TEST(ApiParameters, AnUpdateThatChangesNoValueBuildsNothing) {
  vkpt::Scene scene = Open(kCornell, vkpt::Backend::Cpu);
  scene.Render({}, test::SmallRender(3));
  scene.Update(scene.Parameters());
  scene.Update({});
  scene.Render({}, test::SmallRender(3));
  EXPECT_EQ(Builds(scene), 1u);
}

TEST(ApiParameters, EnvironmentIntensityRendersAsLoadedWithIt) {
  VKPT_REQUIRE_SHARED_DATA();
  const std::string env = test::SharedData("gltf-pbr/environments/venice_sunset_1k.hdr");
  for (vkpt::Backend backend : {vkpt::Backend::Cpu, vkpt::Backend::Vulkan}) {
    vkpt::SceneOptions options;
    options.backend = backend;
    options.environment = env;
    options.environmentIntensity = 2.5f;
    vkpt::Scene fresh(kCornell, options);
    vkpt::Scene live = Open(kCornell, backend, env);
    live.Render({}, test::SmallRender(3));
    EXPECT_EQ(std::get<double>(live.Parameters().at("environment/intensity")), 1.0);
    live.Update({{"environment/intensity", 2.5}});
    EXPECT_EQ(live.Render({}, test::SmallRender(3)).image.data, fresh.Render({}, test::SmallRender(3)).image.data);
    EXPECT_THROW(live.Update({{"environment/intensity", -1.0}}), vkpt::SettingError);
  }
}

}  // namespace
}  // namespace vkpt::internal

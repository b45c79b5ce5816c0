// Scene::Parameters() and Scene::Update(): an edit renders what a fresh load of the file
// so edited renders, bit for bit, on both backends; a refused edit changes nothing; an
// update that changes no value builds nothing again.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
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

// The Cornell box with its first material red and rough and its second metallic, and its
// light twice as strong, written beside a copy of its buffer.
std::string EditedCornell(const test::TempFolder& folder) {
  std::ifstream in(kCornell);
  json file = json::parse(in);
  json& pbr0 = file["materials"][0]["pbrMetallicRoughness"];
  pbr0["baseColorFactor"] = {0.9, 0.1, 0.1, 1.0};
  pbr0["roughnessFactor"] = 0.35;
  file["materials"][1]["pbrMetallicRoughness"]["metallicFactor"] = 0.8;
  json& light = file["materials"][3];
  light["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] =
      2.0 * light["extensions"]["KHR_materials_emissive_strength"].value("emissiveStrength", 1.0);
  std::filesystem::copy_file(test::SourcePath("scenes/cornell.bin"), folder / "cornell.bin");
  std::ofstream(folder / "cornell.gltf") << file.dump();
  return folder / "cornell.gltf";
}

uint32_t Builds(vkpt::Scene& scene) { return vkpt::SceneAccess::Engine(scene).Counts().builds; }

TEST(ApiParameters, AnEditRendersAsTheEditedFile) {
  const test::TempFolder folder("api-parameters");
  const std::string edited = EditedCornell(folder);
  for (vkpt::Backend backend : {vkpt::Backend::Cpu, vkpt::Backend::Vulkan}) {
    vkpt::Scene fresh = Open(edited, backend);
    vkpt::Scene live = Open(kCornell, backend);
    const vkpt::RenderResult before = live.Render({}, test::SmallRender(3));  // built and uploaded before the edit
    live.Update(fresh.Parameters());
    EXPECT_EQ(live.Parameters(), fresh.Parameters());
    const vkpt::RenderResult after = live.Render({}, test::SmallRender(3));
    EXPECT_EQ(after.image.data, fresh.Render({}, test::SmallRender(3)).image.data) << after.engine;
    EXPECT_NE(after.image.data, before.image.data);
    EXPECT_EQ(Builds(live), 2u);
  }
}

TEST(ApiParameters, ARefusedEditChangesNothing) {
  vkpt::Scene scene = Open(kCornell, vkpt::Backend::Cpu);
  const vkpt::ParameterMap original = scene.Parameters();
  const vkpt::RenderResult before = scene.Render({}, test::SmallRender(3));
  const std::vector<std::pair<vkpt::ParameterMap, std::string>> refused = {
      {{{"materials/0/roughness", 0.5}, {"materials/1/roughness", 1.5}}, "materials/1/roughness must be in [0, 1]"},
      {{{"materials/0/base_color", vkpt::Rgb{0.5f, -0.1f, 0.5f}}}, "materials/0/base_color[1] must be in [0, 1]"},
      {{{"materials/0/roughness", vkpt::Rgb{}}}, "takes a number, not an RGB triple"},
      {{{"materials/0/unlit", 1.0}}, "takes a switch, not a number"},
      {{{"materials/99/roughness", 0.5}}, "no scene parameter \"materials/99/roughness\""},
      {{{"materials/0/shininess", 0.5}}, "materials/<0 to 4>/<base_color, alpha"},
      {{{"materials/x/roughness", 0.5}}, "no scene parameter"},
      {{{"materials/00/roughness", 0.5}}, "no scene parameter \"materials/00/roughness\""},
      {{{std::string(1000, 'x'), 0.5}}, "no scene parameter \"" + std::string(80, 'x') + "…\": the keys"},
      {{{"environment/intensity", 2.0}}, "no scene parameter"},  // no environment map
      {{{"materials/0/ior", std::nan("")}}, "materials/0/ior must be in [0, 1e+06], got nan"},
  };
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

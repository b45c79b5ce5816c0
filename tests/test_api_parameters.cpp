// Scene::Parameters() and Scene::Update(): an edit renders what a fresh load of the file
// so edited renders, bit for bit, on both backends; a refused edit changes nothing; an
// update that changes no value builds nothing again, one of materials and lights alone
// builds no BVH.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "api_test_util.h"
#include "test_util.h"
#include "vkpt/scene_access.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal {
namespace {

using nlohmann::json;
using test::Builds;
using test::ExpectEachRefused;
using test::Open;
using test::WriteCornell;

const std::string kCornell = test::Cornell();

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

// The Cornell box's materials and lights edited, its triangles left where they are: the
// white surfaces red and rough, the red wall metallic (a glossy lobe the GPU's kernel had
// no need of), the green wall glowing (two more lights), the lamp twice as bright and the
// point light orange.
void Restyle(json& file) {
  json& pbr0 = file["materials"][0]["pbrMetallicRoughness"];
  pbr0["baseColorFactor"] = {0.9, 0.1, 0.1, 1.0};
  pbr0["roughnessFactor"] = 0.35;
  file["materials"][1]["pbrMetallicRoughness"]["metallicFactor"] = 0.8;
  file["materials"][2]["emissiveFactor"] = {1.0, 0.5, 0.25};
  json& light = file["materials"][3];
  light["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] =
      2.0 * light["extensions"]["KHR_materials_emissive_strength"].value("emissiveStrength", 1.0);
  AddPointLight(file, {1.0, 0.5, 0.25}, 60000.0);
}

uint32_t Restyles(vkpt::Scene& scene) { return vkpt::SceneAccess::Engine(scene).Counts().restyles; }

// Materials and lights alone change no triangle: the BVH stays, the materials and the
// light table are made again and re-uploaded, and the image is the edited file's.
TEST(ApiParameters, MaterialAndLightEditsBuildNoBvh) {
  const test::TempFolder folder("api-parameters-restyle");
  const std::string base = WriteCornell(folder, "base.gltf", [](json& f) { AddPointLight(f, {1, 1, 1}, 30000.0); });
  const std::string edited = WriteCornell(folder, "edited.gltf", Restyle);
  for (vkpt::Backend backend : {vkpt::Backend::Cpu, vkpt::Backend::Vulkan}) {
    vkpt::Scene fresh = Open(edited, backend);
    vkpt::Scene live = Open(base, backend);
    const uint64_t lightsBefore = (live.Render({}, test::SmallRender(3)), live.Stats().lights);
    live.Update(fresh.Parameters());
    const vkpt::RenderResult after = live.Render({}, test::SmallRender(3));
    EXPECT_EQ(after.image.data, fresh.Render({}, test::SmallRender(3)).image.data) << after.engine;
    EXPECT_EQ(Builds(live), 1u);
    EXPECT_EQ(Restyles(live), 1u);
    EXPECT_EQ(live.Stats().lights, fresh.Stats().lights);
    EXPECT_EQ(live.Stats().lights, lightsBefore + 2);  // the green wall's two triangles
  }
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
    // A turn of the map is the scene's for renders that name none, and only a constant.
    vkpt::RenderOptions turned = test::SmallRender(3);
    turned.environmentRotation = 90.0f;
    const vkpt::RenderResult expected = fresh.Render({}, turned);
    live.Update({{"environment/rotation", 90.0}});
    EXPECT_EQ(live.Render({}, test::SmallRender(3)).image.data, expected.image.data);
    EXPECT_EQ(Builds(live), 1u);
    EXPECT_THROW(live.Update({{"environment/rotation", 4000.0}}), vkpt::SettingError);
  }
}

}  // namespace
}  // namespace vkpt::internal

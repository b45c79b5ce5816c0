// Scene::Update of the choices a file offers and of what a render takes by default: a
// variant, an animation and its time, a material that needs tangents. Each renders what
// the scene loaded with that choice (or the file so edited) renders, bit for bit, on both
// backends; a refused choice changes nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "api_test_util.h"
#include "gltf_builder.h"
#include "test_util.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal {
namespace {

using nlohmann::json;
using test::Builds;
using test::Open;

// The Cornell box with two variants, "red" and "green", that paint the tall box (mesh 7)
// with the walls' materials.
void AddVariants(json& file) {
  file["extensionsUsed"].push_back("KHR_materials_variants");
  file["extensions"]["KHR_materials_variants"]["variants"] = {{{"name", "red"}}, {{"name", "green"}}};
  file["meshes"][7]["primitives"][0]["extensions"]["KHR_materials_variants"]["mappings"] = {
      {{"material", 1}, {"variants", {0}}}, {{"material", 2}, {"variants", {1}}}};
}

// And two animations over one second: "spin" turns the tall box (node 7) a quarter about
// +Y, "lift" raises the short box (node 6), in a buffer of their own.
void AddAnimations(json& file) {
  const std::vector<float> times = {0, 1}, turns = {0, 0, 0, 1, 0, 0.70710677f, 0, 0.70710677f},
                           lifts = {0, 0, 0, 0, 120, 0};
  const std::string bytes = test::Bytes(times) + test::Bytes(turns) + test::Bytes(lifts);
  const size_t buffer = file["buffers"].size(), view = file["bufferViews"].size(), in = file["accessors"].size();
  file["buffers"].push_back(
      {{"byteLength", bytes.size()}, {"uri", "data:application/octet-stream;base64," + test::Base64(bytes)}});
  file["bufferViews"].push_back({{"buffer", buffer}, {"byteOffset", 0}, {"byteLength", 8}});
  file["bufferViews"].push_back({{"buffer", buffer}, {"byteOffset", 8}, {"byteLength", 32}});
  file["bufferViews"].push_back({{"buffer", buffer}, {"byteOffset", 40}, {"byteLength", 24}});
  file["accessors"].push_back(
      {{"bufferView", view}, {"componentType", 5126}, {"count", 2}, {"type", "SCALAR"}, {"min", {0}}, {"max", {1}}});
  file["accessors"].push_back({{"bufferView", view + 1}, {"componentType", 5126}, {"count", 2}, {"type", "VEC4"}});
  file["accessors"].push_back({{"bufferView", view + 2}, {"componentType", 5126}, {"count", 2}, {"type", "VEC3"}});
  auto animation = [&](const char* name, size_t output, int node, const char* path) {
    return json{{"name", name},
                {"samplers", {{{"input", in}, {"output", output}}}},
                {"channels", {{{"sampler", 0}, {"target", {{"node", node}, {"path", path}}}}}}};
  };
  file["animations"] = {animation("spin", in + 1, 7, "rotation"), animation("lift", in + 2, 6, "translation")};
}

std::string WriteChoices(const test::TempFolder& folder) {
  return test::WriteCornell(folder, "choices.gltf", [](json& f) {
    AddVariants(f);
    AddAnimations(f);
  });
}

vkpt::Scene OpenWith(const std::string& path, vkpt::Backend backend, const std::string& variant,
                     const std::string& animation) {
  vkpt::SceneOptions options;
  options.backend = backend;
  options.variant = variant;
  options.animation = animation;
  return vkpt::Scene(path, options);
}

vkpt::RenderOptions At(double time) {
  vkpt::RenderOptions o = test::SmallRender(3);
  o.time = time;
  return o;
}

std::vector<float> Image(vkpt::Scene& scene, const vkpt::RenderOptions& options = test::SmallRender(3)) {
  return scene.Render({}, options).image.data;
}

TEST(ApiChoices, AVariantRendersAsLoadedWithIt) {
  const test::TempFolder folder("api-choices-variant");
  const std::string path = WriteChoices(folder);
  for (vkpt::Backend backend : {vkpt::Backend::Cpu, vkpt::Backend::Vulkan}) {
    vkpt::Scene live = Open(path, backend);
    const std::vector<float> own = Image(live);
    EXPECT_EQ(std::get<std::string>(live.Parameters().at("variant")), "");
    for (const char* variant : {"green", "red"}) {
      vkpt::Scene fresh = OpenWith(path, backend, variant, "");
      live.Update({{"variant", std::string(variant)}});
      EXPECT_EQ(live.Parameters(), fresh.Parameters());
      EXPECT_EQ(live.Meshes()[7].primitives[0].material, std::string(variant) == "red" ? 1u : 2u);
      EXPECT_EQ(live.Stats().variant, fresh.Stats().variant);
      EXPECT_EQ(Image(live), Image(fresh)) << variant << " on " << live.Device();
    }
    live.Update({{"variant", std::string("")}});
    EXPECT_EQ(Image(live), own);
  }
}

TEST(ApiChoices, AnAnimationAndItsTimeRenderAsLoadedWithThem) {
  const test::TempFolder folder("api-choices-animation");
  const std::string path = WriteChoices(folder);
  for (vkpt::Backend backend : {vkpt::Backend::Cpu, vkpt::Backend::Vulkan}) {
    vkpt::Scene live = Open(path, backend);
    const std::vector<float> rest = Image(live);
    vkpt::Scene spin = OpenWith(path, backend, "", "spin");
    live.Update({{"animation", std::string("spin")}, {"time", 0.5}});
    EXPECT_EQ(std::get<std::string>(live.Parameters().at("animation")), "spin");
    EXPECT_EQ(Image(live), Image(spin, At(0.5))) << live.Device();
    // A render's own time poses it; the scene's stays for the renders after.
    EXPECT_EQ(Image(live, At(0.25)), Image(spin, At(0.25)));
    EXPECT_EQ(std::get<double>(live.Parameters().at("time")), 0.5);
    EXPECT_EQ(live.Stats().animationTime, 0.25);
    EXPECT_EQ(Image(live), Image(spin, At(0.5)));
    // By index, spelled back by name; the time kept.
    vkpt::Scene lift = OpenWith(path, backend, "", "lift");
    live.Update({{"animation", std::string("1")}});
    EXPECT_EQ(std::get<std::string>(live.Parameters().at("animation")), "lift");
    EXPECT_EQ(live.Stats().animation, 1u);
    EXPECT_EQ(Image(live), Image(lift, At(0.5)));
    live.Update({{"animation", std::string("")}, {"time", 0.0}});
    EXPECT_EQ(Image(live), rest);
    EXPECT_EQ(Builds(live), 6u);  // rest, spin at 0.5, 0.25 and 0.5 again, lift, rest
  }
}

TEST(ApiChoices, ARefusedChoiceChangesNothing) {
  const test::TempFolder folder("api-choices-refused");
  vkpt::Scene scene = Open(WriteChoices(folder), vkpt::Backend::Cpu);
  test::ExpectEachRefused(
      scene, {
                 {{{"variant", std::string("blue")}}, "no such material variant; it has 0 \"red\", 1 \"green\""},
                 {{{"variant", 1.0}}, "variant takes a name, not a number"},
                 {{{"animation", std::string("walk")}}, "no such animation; it has 0 \"spin\", 1 \"lift\""},
                 {{{"time", 1.0}}, "time is 1 but no animation is chosen"},
                 {{{"animation", std::string("spin")}, {"time", -1.0}}, "time must be in [0, 1e+09], got -1"},
                 {{{"animation", std::string("spin")}, {"time", std::nan("")}}, "time must be in"},
                 {{{"environment/rotation", 10.0}}, "no scene parameter"},  // no environment map
                 {{{"materials/0/roughness", 0.5}, {"variant", std::string("blue")}}, "no such material variant"},
             });
  // A render's own time needs an animation as much as the scene's does.
  EXPECT_THROW(scene.Render({}, At(1.0)), vkpt::SettingError);
  scene.Update({{"animation", std::string("spin")}});
  EXPECT_NO_THROW(scene.Render({}, At(1.0)));
}

// A material made anisotropic needs tangents where no material needed them: the meshes
// are decoded again with tangents generated from their texture coordinates, as a load of
// the file so edited generates them.
TEST(ApiChoices, AnisotropyGeneratesTangentsAsLoaded) {
  VKPT_REQUIRE_SHARED_DATA();
  const test::TempFolder folder("api-choices-anisotropy");
  std::ifstream in(test::CorpusPath("valid/BoxTextured/glTF-Embedded/BoxTextured.gltf"));
  json file = json::parse(in);
  std::ofstream(folder / "base.gltf") << file.dump();
  json& material = file["materials"][0];
  material["pbrMetallicRoughness"]["metallicFactor"] = 1.0;
  material["pbrMetallicRoughness"]["roughnessFactor"] = 0.5;
  material["extensions"]["KHR_materials_anisotropy"]["anisotropyStrength"] = 0.75;
  file["extensionsUsed"].push_back("KHR_materials_anisotropy");
  std::ofstream(folder / "edited.gltf") << file.dump();
  for (vkpt::Backend backend : {vkpt::Backend::Cpu, vkpt::Backend::Vulkan}) {
    vkpt::Scene fresh = Open(folder / "edited.gltf", backend);
    vkpt::Scene live = Open(folder / "base.gltf", backend);
    EXPECT_EQ(live.Stats().generatedTangentPrimitives, 0u);
    Image(live);
    live.Update(
        {{"materials/0/metallic", 1.0}, {"materials/0/roughness", 0.5}, {"materials/0/anisotropy_strength", 0.75}});
    EXPECT_EQ(live.Stats().generatedTangentPrimitives, 1u);
    EXPECT_EQ(Image(live), Image(fresh)) << live.Device();
    EXPECT_EQ(Builds(live), 2u);
  }
}

}  // namespace
}  // namespace vkpt::internal

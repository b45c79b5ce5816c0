// The studio environment that lights a scene without lights (render/studio_environment.h):
// its irradiance is what docs/options.md says; a white sphere in it shows its form
// against a darker backdrop on both backends; --background still gives the uniform
// white of a furnace; and the choice between them follows the renders and the edits,
// each render equal to a fresh load's.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "api_test_util.h"
#include "gltf_builder.h"
#include "render/studio_environment.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal {
namespace {

constexpr double kPi = 3.14159265358979323846;

// ∫ L(ω) max(0, n·ω) dω over the sphere, by the midpoint rule.
double Irradiance(glm::vec3 n, int rows = 400) {
  double e = 0.0;
  for (int i = 0; i < rows; ++i) {
    const double theta = kPi * (i + 0.5) / rows;
    for (int j = 0; j < 2 * rows; ++j) {
      const double phi = 2.0 * kPi * (j + 0.5) / (2 * rows);
      const glm::vec3 d(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
      const double c = glm::dot(n, d);
      if (c > 0.0) e += StudioRadiance(d) * c * std::sin(theta) * (kPi / rows) * (kPi / rows);
    }
  }
  return e;
}

TEST(StudioEnvironment, ItsIrradianceIsTheDocumented) {
  // docs/options.md, --background: a white Lambertian surface facing the key, up, the
  // default camera, away from it and down reads E / π.
  EXPECT_NEAR(Irradiance(glm::normalize(kStudioKey.direction)) / kPi, 0.88, 0.01);
  EXPECT_NEAR(Irradiance({0, 1, 0}) / kPi, 0.77, 0.01);
  EXPECT_NEAR(Irradiance({0, 0, 1}) / kPi, 0.53, 0.01);
  EXPECT_NEAR(Irradiance({0, 0, -1}) / kPi, 0.14, 0.01);
  EXPECT_NEAR(Irradiance({0, -1, 0}) / kPi, 0.08, 0.01);
  EXPECT_FLOAT_EQ(StudioRadiance({0, 0, -1}), 0.5f * (kStudioBackdrop + kStudioFloor));  // the horizon
  EXPECT_FLOAT_EQ(StudioRadiance(glm::normalize(glm::vec3(0, 1, -1))), kStudioBackdrop);
  EXPECT_FLOAT_EQ(StudioRadiance({0, -1, 0}), kStudioFloor);
}

TEST(StudioEnvironment, TheMapHoldsTheStudiosEnergy) {
  const EnvironmentMap map = StudioEnvironment();
  double mapped = 0.0;
  for (uint32_t y = 0; y < map.height; ++y)
    for (uint32_t x = 0; x < map.width; ++x)
      mapped += map.texels[size_t(y) * map.width + x].r * std::sin(kPi * (y + 0.5) / map.height);
  mapped *= 2.0 * kPi * kPi / (double(map.width) * map.height);
  double exact = 0.0;
  const int rows = 400;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < 2 * rows; ++j) {
      const double theta = kPi * (i + 0.5) / rows, phi = 2.0 * kPi * (j + 0.5) / (2 * rows);
      exact += StudioRadiance({float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)),
                               float(-std::sin(theta) * std::cos(phi))}) *
               std::sin(theta) * (kPi / rows) * (kPi / rows);
    }
  EXPECT_NEAR(mapped / exact, 1.0, 0.01);
  EXPECT_EQ(map.cdf.size(), size_t(map.width) * map.height + map.height);
}

// A white diffuse UV sphere of radius 1 at the origin, no lights, no camera.
std::string WhiteSphere() {
  std::vector<glm::vec3> p;
  std::vector<uint32_t> idx;
  const int rings = 24, segments = 48;
  for (int r = 0; r <= rings; ++r)
    for (int s = 0; s <= segments; ++s) {
      const double theta = kPi * r / rings, phi = 2.0 * kPi * s / segments;
      p.emplace_back(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const uint32_t a = r * (segments + 1) + s, b = a + segments + 1;
      idx.insert(idx.end(), {a, a + 1, b, a + 1, b + 1, b});
    }
  test::GltfBuilder g;
  g.materials.push_back(R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1],"metallicFactor":0}})");
  g.Mesh(g.Positions(p), g.Indices(idx), 0);
  g.Node(R"({"mesh":0})");
  return g.Json();
}

vkpt::RenderOptions Small() {
  vkpt::RenderOptions o;
  o.width = o.height = 48;
  o.spp = 64;
  return o;
}

float Luminance(const vkpt::Image& image, uint32_t x, uint32_t y) {
  return 0.2126f * image.At(x, y, 0) + 0.7152f * image.At(x, y, 1) + 0.0722f * image.At(x, y, 2);
}

TEST(StudioEnvironment, AWhiteSphereShowsItsFormAgainstADarkerBackdrop) {
  const test::TempFile sphere(WhiteSphere());
  std::vector<double> means;
  for (const vkpt::Backend backend : {vkpt::Backend::Cpu, vkpt::Backend::Vulkan}) {
    vkpt::Scene scene = test::Open(sphere.path, backend);
    const vkpt::Image image = scene.Render({}, Small()).image;
    const float backdrop = Luminance(image, 1, 1), lit = Luminance(image, 30, 15), shade = Luminance(image, 15, 33);
    EXPECT_NEAR(backdrop, kStudioBackdrop, 0.01f) << scene.Device();
    EXPECT_GT(lit, 3.0f * backdrop) << scene.Device();
    EXPECT_GT(lit, 3.0f * shade) << scene.Device();
    double sum = 0.0;
    for (float v : image.data) sum += v;
    means.push_back(sum / image.data.size());
    // The furnace of old on request: a white world, uniform behind the sphere.
    vkpt::RenderOptions white = Small();
    white.background = {{1.0f, 1.0f, 1.0f}};
    const vkpt::Image furnace = scene.Render({}, white).image;
    EXPECT_EQ(furnace.At(1, 1), 1.0f);
    EXPECT_NEAR(Luminance(furnace, 24, 24), 1.0f, 0.05f) << scene.Device();
  }
  EXPECT_NEAR(means[1] / means[0], 1.0, 0.02);  // the device lights it as the CPU does
}

TEST(StudioEnvironment, TheChoiceFollowsRendersAndEditsAsFreshLoadsWould) {
  const test::TempFolder folder("studio");
  const auto unlit = [](nlohmann::json& f) { f["materials"][3]["emissiveFactor"] = {0.0, 0.0, 0.0}; };
  const std::string dark = test::WriteCornell(folder, "dark.gltf", unlit);
  vkpt::RenderOptions white = test::SmallRender();
  white.background = {{1.0f, 1.0f, 1.0f}};
  const vkpt::RenderResult studioFresh = test::Open(dark, vkpt::Backend::Cpu).Render({}, test::SmallRender());
  const vkpt::RenderResult whiteFresh = test::Open(dark, vkpt::Backend::Cpu).Render({}, white);
  const vkpt::RenderResult litFresh = test::Open(test::Cornell(), vkpt::Backend::Cpu).Render({}, test::SmallRender());
  EXPECT_NE(studioFresh.image.data, whiteFresh.image.data);

  vkpt::Scene scene = test::Open(dark, vkpt::Backend::Cpu);
  EXPECT_EQ(scene.Render({}, test::SmallRender()).image.data, studioFresh.image.data);
  EXPECT_EQ(scene.Render({}, white).image.data, whiteFresh.image.data);
  EXPECT_EQ(scene.Render({}, test::SmallRender()).image.data, studioFresh.image.data);
  EXPECT_EQ(test::Builds(scene), 3u);  // the studio in, out and in again
  scene.Render({}, test::SmallRender());
  EXPECT_EQ(test::Builds(scene), 3u);  // the same choice: nothing built

  // The light's emission back through Update: the studio goes; and off again: it returns.
  vkpt::Scene edited = test::Open(dark, vkpt::Backend::Cpu);
  edited.Render({}, test::SmallRender());
  const vkpt::ParameterMap lit = test::Open(test::Cornell(), vkpt::Backend::Cpu).Parameters();
  edited.Update({{"materials/3/emission", lit.at("materials/3/emission")}});
  EXPECT_EQ(edited.Render({}, test::SmallRender()).image.data, litFresh.image.data);
  edited.Update({{"materials/3/emission", vkpt::Rgb{0.0f, 0.0f, 0.0f}}});
  EXPECT_EQ(edited.Render({}, test::SmallRender()).image.data, studioFresh.image.data);
}

}  // namespace
}  // namespace vkpt::internal

// KHR_lights_punctual: lights placed by their nodes, their units and cones, and the
// errors a malformed light must produce.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gltf/gltf_loader.h"
#include "gltf_builder.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

using namespace test;

// The triangle model with `lights` (a JSON array) and nodes 1.. holding them under root
// node 0, which also holds the mesh.
GltfBuilder LightModel(const std::string& lights, const std::vector<std::string>& lightNodes) {
  GltfBuilder b = TriangleModel();
  std::string children;
  for (size_t i = 0; i < lightNodes.size(); ++i) {
    if (i) children += ',';
    children += std::to_string(i + 1);
  }
  b.Node(R"({"mesh":0,"children":[)" + children + "]}");
  for (const std::string& node : lightNodes) b.Node(node);
  b.extensionsUsed = {"KHR_lights_punctual"};
  b.extraTopLevel = R"(,"extensions":{"KHR_lights_punctual":{"lights":)" + lights + "}}";
  return b;
}

std::string LightNode(int light, const std::string& fields = "") {
  return R"({"extensions":{"KHR_lights_punctual":{"light":)" + std::to_string(light) + "}}" + fields + "}";
}

TEST(Lights, PointSpotAndDirectional) {
  const double h = std::sqrt(0.5);  // 90° about +X: −Z → +Y
  GltfBuilder b = LightModel(
      R"([{"type":"point","color":[1,0.5,0.25],"intensity":20,"range":7,"name":"bulb"},
          {"type":"spot","intensity":3,"spot":{"innerConeAngle":0.25,"outerConeAngle":0.5}},
          {"type":"directional","intensity":2}])",
      {LightNode(0, R"(,"translation":[1,2,3],"scale":[5,5,5])"),
       LightNode(1, R"(,"translation":[0,4,0],"rotation":[)" + Num(h) + ",0,0," + Num(h) + R"(],"scale":[1,9,2])"),
       LightNode(2, R"(,"matrix":[2,0,0,0, 0,2,0,0, 0,0,2,0, 9,9,9,1])")});
  Scene s = Load(b);
  ASSERT_EQ(s.lights.size(), 3u);
  EXPECT_TRUE(s.ignoredFeatures.empty()) << ::testing::PrintToString(s.ignoredFeatures);

  const PunctualLight& point = s.lights[0];
  EXPECT_EQ(point.type, PunctualLight::Type::kPoint);
  EXPECT_EQ(point.name, "bulb");
  EXPECT_TRUE(Near(point.position, {1, 2, 3}));
  EXPECT_TRUE(Near(point.intensity, {20, 10, 5})) << "color × intensity, unscaled by the node";
  EXPECT_FLOAT_EQ(point.range, 7.0f);

  const PunctualLight& spot = s.lights[1];
  EXPECT_EQ(spot.type, PunctualLight::Type::kSpot);
  EXPECT_EQ(spot.name, "nodes[2]");
  EXPECT_TRUE(Near(spot.position, {0, 4, 0}));
  EXPECT_TRUE(Near(spot.direction, {0, 1, 0})) << "local −Z rotated 90° about +X, unit despite the scale";
  EXPECT_TRUE(Near(spot.intensity, {3, 3, 3})) << "color defaults to white";
  EXPECT_FLOAT_EQ(spot.range, 0.0f);
  EXPECT_FLOAT_EQ(spot.cosInner, std::cos(0.25f));
  EXPECT_FLOAT_EQ(spot.cosOuter, std::cos(0.5f));

  const PunctualLight& sun = s.lights[2];
  EXPECT_EQ(sun.type, PunctualLight::Type::kDirectional);
  EXPECT_TRUE(Near(sun.direction, {0, 0, -1}));
  EXPECT_TRUE(Near(sun.intensity, {2, 2, 2}));
}

TEST(Lights, SpotConeDefaultsAndInstancing) {
  // One light instanced by two nodes; the spot's cone defaults to 0 and π/4.
  GltfBuilder b = LightModel(R"([{"type":"spot","spot":{}}])",
                             {LightNode(0, R"(,"translation":[1,0,0])"), LightNode(0, R"(,"translation":[2,0,0])")});
  Scene s = Load(b);
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_TRUE(Near(s.lights[1].position, {2, 0, 0}));
  EXPECT_FLOAT_EQ(s.lights[0].cosInner, 1.0f);
  EXPECT_FLOAT_EQ(s.lights[0].cosOuter, std::cos(0.78539816f));
}

TEST(Lights, LightsOutsideTheRenderedSceneAreNotPlaced) {
  GltfBuilder b = LightModel(R"([{"type":"point"}])", {});
  b.Node(LightNode(0));  // node 1: a root not in scene 0
  Scene s = Load(b);
  EXPECT_TRUE(s.lights.empty());
}

TEST(Lights, InvalidLightsAreNamed) {
  const std::vector<std::string> node = {LightNode(0)};
  EXPECT_TRUE(FailsWith(LightModel(R"([{"type":"area"}])", node), {"lights[0].type", "area"}));
  EXPECT_TRUE(FailsWith(LightModel(R"([{"type":"point","color":[1,1]}])", node), {"lights[0].color", "3 numbers"}));
  EXPECT_TRUE(FailsWith(LightModel(R"([{"type":"point","color":[1,2,1]}])", node), {"lights[0].color", "[0, 1]"}));
  EXPECT_TRUE(FailsWith(LightModel(R"([{"type":"point","intensity":-1}])", node), {"lights[0].intensity", ">= 0"}));
  EXPECT_TRUE(FailsWith(LightModel(R"([{"type":"point","range":-2}])", node), {"lights[0].range", "> 0"}));
  EXPECT_TRUE(FailsWith(LightModel(R"([{"type":"spot","spot":{"innerConeAngle":0.5,"outerConeAngle":0.5}}])", node),
                        {"lights[0].spot", "innerConeAngle < outerConeAngle"}));
  EXPECT_TRUE(
      FailsWith(LightModel(R"([{"type":"spot","spot":{"outerConeAngle":2}}])", node), {"lights[0].spot", "<= π/2"}));
  EXPECT_TRUE(FailsWith(LightModel(R"([{"type":"spot","spot":{"innerConeAngle":-0.1}}])", node),
                        {"lights[0].spot", "0 <= innerConeAngle"}));
  // Unreferenced lights are checked too.
  EXPECT_TRUE(
      FailsWith(LightModel(R"([{"type":"point"},{"type":"point","intensity":-1}])", node), {"lights[1].intensity"}));
}

TEST(Lights, InvalidLightNodesAreNamed) {
  const std::string lights = R"([{"type":"directional"}])";
  EXPECT_TRUE(FailsWith(LightModel(lights, {LightNode(1)}), {"nodes[1].extensions.KHR_lights_punctual.light", "1"}));
  EXPECT_TRUE(FailsWith(LightModel(lights, {R"({"extensions":{"KHR_lights_punctual":{}}})"}),
                        {"nodes[1].extensions.KHR_lights_punctual", "light index"}));
  EXPECT_TRUE(FailsWith(LightModel(lights, {R"({"extensions":{"KHR_lights_punctual":{"light":0.5}}})"}),
                        {"nodes[1].extensions.KHR_lights_punctual.light", "integer"}));
  EXPECT_TRUE(FailsWith(LightModel(lights, {LightNode(0, R"(,"scale":[1,1,0])")}), {"nodes[1]", "degenerate"}));
}

TEST(Lights, LightsPunctualLampHasFivePointLights) {
  // The Khronos sample model, in gltf-pbr/ of the test data.
  VKPT_REQUIRE_SHARED_DATA();
  const std::string path = test::SharedData("gltf-pbr/LightsPunctualLamp/glTF/LightsPunctualLamp.gltf");
  Scene s = LoadGltf(path);
  int points = 0;
  for (const PunctualLight& l : s.lights) points += l.type == PunctualLight::Type::kPoint;
  EXPECT_EQ(s.lights.size(), 5u);
  EXPECT_EQ(points, 5);
}

}  // namespace
}  // namespace vkpt::internal

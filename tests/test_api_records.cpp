// What vkpt::Scene says it holds (vkpt/scene_info.h) against the files' own JSON: the
// materials' names, factors and textures, the cameras, the punctual lights, the
// animations and variants; and the counts of Stats() before and after a render.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "api_test_util.h"
#include "test_util.h"

#include "vkpt/vkpt.h"

namespace vkpt::internal {
namespace {

using nlohmann::json;

json ReadJson(const std::string& path) {
  std::ifstream in(path);
  return json::parse(in);
}

vkpt::Scene OnCpu(const std::string& path) {
  vkpt::SceneOptions options;
  options.backend = vkpt::Backend::Cpu;
  return vkpt::Scene(path, options);
}

void ExpectRgb(const vkpt::Rgb& actual, const json& factor, float scale = 1.0f) {
  for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(actual[c], factor[c].get<float>() * scale) << "channel " << c;
}

TEST(ApiRecords, CornellMaterialsAreTheFilesFactors) {
  const std::string path = test::SourcePath("scenes/cornell.gltf");
  const json file = ReadJson(path);
  const std::vector<vkpt::MaterialInfo> materials = OnCpu(path).Materials();
  ASSERT_EQ(materials.size(), file["materials"].size() + 1);  // vkpt's default last
  for (size_t i = 0; i < file["materials"].size(); ++i) {
    SCOPED_TRACE("material " + std::to_string(i));
    const json& m = file["materials"][i];
    const vkpt::MaterialInfo& info = materials[i];
    EXPECT_EQ(info.index, i);
    EXPECT_EQ(info.name, m["name"].get<std::string>());
    const json& pbr = m["pbrMetallicRoughness"];
    ExpectRgb(info.baseColor, pbr.value("baseColorFactor", json{1, 1, 1, 1}));
    EXPECT_FLOAT_EQ(info.metallic, pbr.value("metallicFactor", 1.0f));
    EXPECT_FLOAT_EQ(info.roughness, pbr.value("roughnessFactor", 1.0f));
    const json strength =
        m.value("extensions", json::object()).value("KHR_materials_emissive_strength", json::object());
    ExpectRgb(info.emission, m.value("emissiveFactor", json{0, 0, 0}), strength.value("emissiveStrength", 1.0f));
    EXPECT_EQ(info.alphaMode, m.value("alphaMode", "OPAQUE"));
    EXPECT_EQ(info.doubleSided, m.value("doubleSided", false));
    EXPECT_TRUE(info.textures.empty());
  }
  EXPECT_EQ(materials.back().index, file["materials"].size());
}

TEST(ApiRecords, CornellCameraAndStatsBeforeAndAfterARender) {
  const std::string path = test::SourcePath("scenes/cornell.gltf");
  const json file = ReadJson(path);
  vkpt::Scene scene = OnCpu(path);
  const std::vector<vkpt::CameraInfo> cameras = scene.Cameras();
  ASSERT_EQ(cameras.size(), file["cameras"].size());
  EXPECT_NEAR(cameras[0].yfovDegrees, file["cameras"][0]["perspective"]["yfov"].get<double>() * 180.0 / M_PI, 1e-4);
  EXPECT_FALSE(cameras[0].orthographic);
  EXPECT_TRUE(scene.Lights().empty());  // the ceiling emits; it is no punctual light
  EXPECT_TRUE(scene.Animations().empty());
  EXPECT_TRUE(scene.Variants().empty());

  const vkpt::SceneStats loaded = scene.Stats();
  EXPECT_EQ(loaded.path, path);
  EXPECT_GT(loaded.triangles, 0u);
  EXPECT_NE(loaded.contentHash, 0u);
  EXPECT_GT(loaded.memoryCounted, 0u);
  EXPECT_LE(loaded.memoryCounted, loaded.memoryLimit);
  EXPECT_FALSE(loaded.variant || loaded.animation);
  for (int a = 0; a < 3; ++a) EXPECT_LT(loaded.boundsMin[a], loaded.boundsMax[a]);

  vkpt::RenderOptions options;
  options.width = options.height = 8;
  options.spp = 1;
  scene.Render({}, options);
  const vkpt::SceneStats built = scene.Stats();
  EXPECT_EQ(built.triangles, loaded.triangles);
  EXPECT_GT(built.lights, 0u);  // the ceiling's emissive triangles
  EXPECT_GT(built.bvh.nodes, 0u);
  EXPECT_GE(built.bvh.references, built.triangles - built.degenerateTriangles);
  EXPECT_TRUE(built.bvh.splits == "object" || built.bvh.splits == "spatial") << built.bvh.splits;
}

TEST(ApiRecords, VariantsAndTexturesAreTheFiles) {
  VKPT_REQUIRE_SHARED_DATA();
  const std::string path = test::SharedData("gltf-ext/MaterialsVariantsShoe/glTF/MaterialsVariantsShoe.gltf");
  const json file = ReadJson(path);
  const vkpt::Scene scene = OnCpu(path);
  const json& variants = file["extensions"]["KHR_materials_variants"]["variants"];
  const std::vector<std::string> names = scene.Variants();
  ASSERT_EQ(names.size(), variants.size());
  for (size_t i = 0; i < names.size(); ++i) EXPECT_EQ(names[i], variants[i]["name"].get<std::string>());
  const std::vector<vkpt::MaterialInfo> materials = scene.Materials();
  for (size_t i = 0; i < file["materials"].size(); ++i) {
    const json& base = file["materials"][i]["pbrMetallicRoughness"]["baseColorTexture"];
    ASSERT_EQ(materials[i].textures.count("baseColor"), 1u) << "material " << i;
    EXPECT_EQ(materials[i].textures.at("baseColor").texture, base["index"].get<uint32_t>());
    EXPECT_EQ(materials[i].textures.at("baseColor").texCoord, base.value("texCoord", 0u));
  }
}

TEST(ApiRecords, PunctualLightsAreTheFilesColourTimesIntensity) {
  VKPT_REQUIRE_SHARED_DATA();
  const std::string path = test::SharedData("gltf-pbr/LightsPunctualLamp/glTF/LightsPunctualLamp.gltf");
  const json file = ReadJson(path);
  const json& declared = file["extensions"]["KHR_lights_punctual"]["lights"];
  std::vector<size_t> placed;  // the light of each light node, in scene-graph order
  std::function<void(uint32_t)> visit = [&](uint32_t n) {
    const json& node = file["nodes"][n];
    if (node.contains("extensions") && node["extensions"].contains("KHR_lights_punctual"))
      placed.push_back(node["extensions"]["KHR_lights_punctual"]["light"].get<size_t>());
    for (const json& child : node.value("children", json::array())) visit(child.get<uint32_t>());
  };
  for (const json& root : file["scenes"][file.value("scene", 0)]["nodes"]) visit(root.get<uint32_t>());
  const std::vector<vkpt::LightInfo> lights = OnCpu(path).Lights();
  ASSERT_EQ(lights.size(), placed.size());
  for (size_t i = 0; i < lights.size(); ++i) {
    SCOPED_TRACE("light " + std::to_string(i));
    EXPECT_EQ(lights[i].index, i);
    const json& light = declared[placed[i]];
    EXPECT_EQ(lights[i].light, placed[i]);
    EXPECT_EQ(lights[i].type, light["type"].get<std::string>());
    ExpectRgb(lights[i].color, light.value("color", json{1, 1, 1}));
    EXPECT_FLOAT_EQ(float(lights[i].intensity), light.value("intensity", 1.0f));
  }
}

TEST(ApiRecords, AnimationsHaveTheFilesNamesAndDurations) {
  VKPT_REQUIRE_SHARED_DATA();
  const std::string path = test::SharedData("gltf-ext/AnimatedCube/glTF/AnimatedCube.gltf");
  const json file = ReadJson(path);
  const std::vector<vkpt::AnimationInfo> animations = OnCpu(path).Animations();
  ASSERT_EQ(animations.size(), file["animations"].size());
  for (size_t i = 0; i < animations.size(); ++i) {
    const json& a = file["animations"][i];
    double end = 0.0;  // the last key of any of its samplers
    for (const json& sampler : a["samplers"])
      end = std::max(end, file["accessors"][sampler["input"].get<size_t>()]["max"][0].get<double>());
    EXPECT_EQ(animations[i].name, a["name"].get<std::string>());
    EXPECT_NEAR(animations[i].duration, end, 1e-6);
  }
}

// glm's matrix of a record's translation, rotation and scale.
glm::dmat4 Local(const vkpt::NodeInfo& n) {
  const glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);
  return glm::translate(glm::dmat4(1.0), glm::dvec3(n.translation[0], n.translation[1], n.translation[2])) *
         glm::mat4_cast(q) * glm::scale(glm::dmat4(1.0), glm::dvec3(n.scale[0], n.scale[1], n.scale[2]));
}

TEST(ApiRecords, CornellNodesAndMeshesAreTheFiles) {
  const std::string path = test::SourcePath("scenes/cornell.gltf");
  const json file = ReadJson(path);
  vkpt::Scene scene = OnCpu(path);
  const std::vector<vkpt::NodeInfo> nodes = scene.Nodes();
  ASSERT_EQ(nodes.size(), file["nodes"].size());
  for (size_t i = 0; i < nodes.size(); ++i) {
    const json& n = file["nodes"][i];
    EXPECT_EQ(nodes[i].index, i);
    EXPECT_EQ(nodes[i].name, n.value("name", ""));
    EXPECT_EQ(nodes[i].mesh, n.contains("mesh") ? std::optional<uint32_t>(n["mesh"]) : std::nullopt);
    EXPECT_EQ(nodes[i].camera, n.contains("camera") ? std::optional<uint32_t>(n["camera"]) : std::nullopt);
    EXPECT_FALSE(nodes[i].light || nodes[i].matrix);
    ExpectRgb(nodes[i].translation, n.value("translation", json{0, 0, 0}));
    for (int c = 0; c < 4; ++c) EXPECT_EQ(nodes[i].rotation[c], n.value("rotation", json{0, 0, 0, 1})[c].get<float>());
    ExpectRgb(nodes[i].scale, n.value("scale", json{1, 1, 1}));
  }
  const std::vector<vkpt::MeshInfo> meshes = scene.Meshes();
  ASSERT_EQ(meshes.size(), file["meshes"].size());
  for (size_t i = 0; i < meshes.size(); ++i) {
    const json& primitives = file["meshes"][i]["primitives"];
    EXPECT_EQ(meshes[i].name, file["meshes"][i].value("name", ""));
    ASSERT_EQ(meshes[i].primitives.size(), primitives.size());
    for (size_t p = 0; p < primitives.size(); ++p) {
      EXPECT_EQ(meshes[i].primitives[p].material, primitives[p]["material"].get<uint32_t>());
      EXPECT_EQ(meshes[i].primitives[p].triangles,
                file["accessors"][primitives[p]["indices"].get<size_t>()]["count"].get<uint64_t>() / 3);
    }
  }
}

// A skinned model whose nodes are placed by matrices: each record is the matrix's
// decomposition, flagged; an edit of one part replaces the matrix by all three.
TEST(ApiRecords, MatrixNodesAreDecomposedAndEditedAsTrs) {
  VKPT_REQUIRE_SHARED_DATA();
  const std::string path = test::SharedData("gltf-ext/RiggedSimple/glTF-Binary/RiggedSimple.glb");
  const std::string glb = test::ReadFile(path);
  uint32_t jsonLength = 0;
  std::memcpy(&jsonLength, glb.data() + 12, 4);
  const json file = json::parse(glb.substr(20, jsonLength));
  vkpt::Scene scene = OnCpu(path);
  const std::vector<vkpt::NodeInfo> nodes = scene.Nodes();
  ASSERT_EQ(nodes.size(), file["nodes"].size());
  for (size_t i = 0; i < nodes.size(); ++i) {
    SCOPED_TRACE("node " + std::to_string(i));
    const json& n = file["nodes"][i];
    EXPECT_EQ(nodes[i].name, n["name"].get<std::string>());
    EXPECT_EQ(nodes[i].children, n.value("children", std::vector<uint32_t>{}));
    EXPECT_EQ(nodes[i].matrix, n.contains("matrix"));
    if (!n.contains("matrix")) continue;
    const glm::dmat4 local = Local(nodes[i]);
    for (int k = 0; k < 16; ++k) EXPECT_NEAR(local[k / 4][k % 4], n["matrix"][k].get<double>(), 1e-6) << k;
  }
  EXPECT_EQ(nodes[2].mesh, 0u);
  const vkpt::NodeInfo before = nodes[1];
  scene.Update({{"nodes/1/translation", vkpt::Vec3{0.0f, 2.0f, 0.0f}}});
  const vkpt::NodeInfo after = scene.Nodes()[1];
  EXPECT_FALSE(after.matrix);
  EXPECT_EQ(after.translation, (vkpt::Vec3{0.0f, 2.0f, 0.0f}));
  EXPECT_EQ(after.rotation, before.rotation);
  EXPECT_EQ(after.scale, before.scale);
  EXPECT_GT(scene.Render({}, test::SmallRender(1)).samples, 0u);
}

}  // namespace
}  // namespace vkpt::internal

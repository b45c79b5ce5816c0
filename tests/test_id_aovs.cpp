// The id AOVs (object_id, material_id, instance_id; shaders/shared/aov.h, scene/scene_ids.h):
// exact ids per pixel on a scene of known squares on both backends, whatever the samples
// and seed; what an alpha-masked surface lets through; no blended value at any edge of the
// Cornell box; the names of the ids; the files the command line writes.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gltf_builder.h"
#include "image/aov_files.h"
#include "scene/scene_ids.h"
#include "session/aov.h"
#include "test_util.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal {
namespace {

using namespace test;

// Unit squares [0, 1]² at z = 0 (front face +Z), seen by an orthographic camera from
// z = 10 over x ∈ [−4, 4], y ∈ [−2, 2]: at 64 × 32 pixels every square's edges fall on
// pixel boundaries, so each pixel's centre lies 1/16 inside one square or outside all.
//   nodes[0] "Left"   mesh "red square" (material "Red") at x ∈ [−3, −2], y ∈ [−1, 0]
//   nodes[1] "Right"  mesh "blue square" (material "Blue") at x ∈ [2, 3], y ∈ [0, 1]
//   nodes[2] (no name) "red square" twice by EXT_mesh_gpu_instancing: x ∈ [−1, 0], y ∈ [−1, 0]
//                      and x ∈ [0, 1], y ∈ [0, 1]
//   nodes[3] "Camera"
//   nodes[4] "Veil"   a square of materials[2], alpha-masked away everywhere, at z = 1
//                      in front of "Right"
constexpr uint32_t kWidth = 64, kHeight = 32;

std::string SquaresFile() {
  GltfBuilder b;
  const int square = b.Positions({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  const int corners = b.Indices({0, 1, 2, 0, 2, 3});
  b.Mesh(square, corners, 0);
  b.Mesh(square, corners, 1);
  b.Mesh(square, corners, 2);
  b.meshes[0].insert(1, R"("name":"red square",)");
  b.meshes[1].insert(1, R"("name":"blue square",)");
  b.materials = {R"({"name":"Red","pbrMetallicRoughness":{"baseColorFactor":[0.8,0.1,0.1,1]}})",
                 R"({"name":"Blue","pbrMetallicRoughness":{"baseColorFactor":[0.1,0.1,0.8,1]}})",
                 R"({"alphaMode":"MASK","pbrMetallicRoughness":{"baseColorFactor":[1,1,1,0]}})"};
  b.Node(R"({"name":"Left","mesh":0,"translation":[-3,-1,0]})");
  b.Node(R"({"name":"Right","mesh":1,"translation":[2,0,0]})");
  const int moves = b.Accessor(b.View(Bytes(std::vector<float>{-1, 0, 0, 0, 1, 0})), kFloat, 2, "VEC3");
  b.Node(R"({"mesh":0,"translation":[0,-1,0],"extensions":{"EXT_mesh_gpu_instancing":{"attributes":{"TRANSLATION":)" +
         std::to_string(moves) + "}}}}");
  b.Node(R"({"name":"Camera","camera":0,"translation":[0,0,10]})");
  b.Node(R"({"name":"Veil","mesh":2,"translation":[2,0,1]})");
  b.cameras = {R"({"type":"orthographic","orthographic":{"xmag":4,"ymag":2,"znear":0.1,"zfar":100}})"};
  b.scenes = {R"({"nodes":[0,1,2,3,4]})"};
  b.extensionsUsed = b.extensionsRequired = {"EXT_mesh_gpu_instancing"};
  return b.Json();
}

// The ids at the centre of pixel (px, py): object, material, instance (−1: nothing).
std::array<float, 3> ExpectedIds(uint32_t px, uint32_t py) {
  const float x = -4.0f + (px + 0.5f) * 0.125f, y = 2.0f - (py + 0.5f) * 0.125f;
  struct Square {
    float x, y;
    std::array<float, 3> ids;
  };
  const Square squares[] = {{-3, -1, {0, 0, 0}}, {2, 0, {1, 1, 1}}, {-1, -1, {2, 0, 2}}, {0, 0, {2, 0, 3}}};
  for (const Square& s : squares)
    if (x > s.x && x < s.x + 1 && y > s.y && y < s.y + 1) return s.ids;
  return {-1, -1, -1};
}

vkpt::RenderResult RenderIds(vkpt::Scene& scene, uint32_t spp, uint32_t seed) {
  vkpt::RenderOptions o;
  o.width = kWidth;
  o.spp = spp;
  o.seed = seed;
  o.aovs = {"object_id", "material_id", "instance_id"};
  return scene.Render(vkpt::Camera{}, o);
}

TEST(IdAovs, LoaderRecordsEachTrianglesNodeAndInstance) {
  const TempFile file(SquaresFile());
  const auto s = LoadGltf(file.path);  // Scene; the API has a Scene too
  ASSERT_EQ(s.triangles.size(), 10u);  // 5 squares
  const std::vector<std::array<int64_t, 3>> expected = {{0, 0, 0}, {1, 1, 1}, {2, 0, 2}, {2, 0, 3}, {4, 2, 4}};
  for (uint32_t t = 0; t < 10; ++t) {
    const TriangleIds ids = IdsOfTriangle(s, t);
    EXPECT_EQ(ids.object, expected[t / 2][0]) << "triangle " << t;
    EXPECT_EQ(ids.material, expected[t / 2][1]) << "triangle " << t;
    EXPECT_EQ(ids.instance, expected[t / 2][2]) << "triangle " << t;
  }
  const TriangleIds none = IdsOfTriangle(s, 0xFFFFFFFFu);
  EXPECT_EQ(none.object, -1);
  EXPECT_EQ(none.material, -1);
  EXPECT_EQ(none.instance, -1);
}

TEST(IdAovs, EveryPixelHoldsItsSquaresIdsOnBothBackends) {
  const TempFile file(SquaresFile());
  for (vkpt::Backend backend : {vkpt::Backend::Cpu, vkpt::Backend::Vulkan}) {
    vkpt::SceneOptions options;
    options.backend = backend;
    vkpt::Scene scene(file.path, options);
    const char* name = backend == vkpt::Backend::Cpu ? "CPU" : "GPU";
    // The ids come from the pixel's centre alone: any sample count and seed gives them.
    for (const auto& [spp, seed] : {std::pair<uint32_t, uint32_t>{1, 0}, {16, 7}}) {
      const vkpt::RenderResult r = RenderIds(scene, spp, seed);
      int wrong = 0;
      for (int k = 0; k < 3; ++k) {
        const vkpt::Image& layer = r.aovs.at(k == 0 ? "object_id" : k == 1 ? "material_id" : "instance_id");
        ASSERT_EQ(layer.width, kWidth);
        ASSERT_EQ(layer.height, kHeight);
        ASSERT_EQ(layer.channels, 1u);
        EXPECT_EQ(layer.channelNames, std::vector<std::string>{"ID"});
        for (uint32_t y = 0; y < kHeight; ++y)
          for (uint32_t x = 0; x < kWidth; ++x) wrong += layer.At(x, y) != ExpectedIds(x, y)[k];
      }
      EXPECT_EQ(wrong, 0) << name << ", " << spp << " spp, seed " << seed;
    }
  }
}

TEST(IdAovs, ACornellBoxEdgeHoldsOneObjectsIdNotABlend) {
  // Perspective edges cross pixels: every value must still be a node's index (or −1), and
  // the two backends' walks agree but for rays that graze an edge.
  std::vector<float> ids[2];
  for (int gpu = 0; gpu < 2; ++gpu) {
    vkpt::SceneOptions options;
    options.backend = gpu ? vkpt::Backend::Vulkan : vkpt::Backend::Cpu;
    vkpt::Scene scene(SourcePath("scenes/cornell.gltf"), options);
    vkpt::RenderOptions o;
    o.width = 96;
    o.spp = 4;
    o.aovs = {"object_id"};
    ids[gpu] = scene.Render(vkpt::Camera{}, o).aovs.at("object_id").data;
  }
  std::set<float> seen;
  int differ = 0;
  for (size_t i = 0; i < ids[0].size(); ++i) {
    seen.insert(ids[0][i]);
    seen.insert(ids[1][i]);
    differ += ids[0][i] != ids[1][i];
  }
  EXPECT_EQ(seen, (std::set<float>{-1, 0, 1, 2, 3, 4, 5, 6, 7}));
  std::printf("Cornell box object_id, 96 x 96: %d pixels differ between the backends (grazing edges)\n", differ);
  EXPECT_LE(differ, 4);
}

TEST(IdAovs, NamesSayWhatEachIdIs) {
  const TempFile file(SquaresFile());
  vkpt::SceneOptions options;
  options.backend = vkpt::Backend::Cpu;
  vkpt::Scene scene(file.path, options);
  const vkpt::RenderResult r = RenderIds(scene, 1, 0);
  const nlohmann::json names = nlohmann::json::parse(r.ids);
  EXPECT_EQ(names["none"], -1);
  EXPECT_EQ(names["object_id"], nlohmann::json::parse(R"j([
    {"id": 0, "name": "Left", "mesh": "red square"}, {"id": 1, "name": "Right", "mesh": "blue square"},
    {"id": 2, "name": "nodes[2]", "mesh": "red square"}, {"id": 4, "name": "Veil", "mesh": "meshes[2]"}])j"));
  EXPECT_EQ(names["material_id"], nlohmann::json::parse(R"j([{"id": 0, "name": "Red"}, {"id": 1, "name": "Blue"},
    {"id": 2, "name": "materials[2]"}, {"id": 3, "name": "(default)"}])j"));
  EXPECT_EQ(names["instance_id"], nlohmann::json::parse(R"j([{"id": 0, "object_id": 0, "placement": 0},
    {"id": 1, "object_id": 1, "placement": 0}, {"id": 2, "object_id": 2, "placement": 0},
    {"id": 3, "object_id": 2, "placement": 1}, {"id": 4, "object_id": 4, "placement": 0}])j"));
  vkpt::RenderOptions plain;
  plain.width = 8;
  plain.spp = 1;
  plain.aovs = {"depth"};
  EXPECT_EQ(scene.Render(vkpt::Camera{}, plain).ids, "");
}

TEST(IdAovs, CommandLineWritesTheNamesBesideTheImage) {
  const TempFile file(SquaresFile());
  const std::string dir = FreshTempDirectory("id-aovs");
  const ProcessResult r = RunVkpt({"--scene", file.path, "--backend", "cpu", "--spp", "1", "--width", "64", "--aov",
                                   "object_id,material_id", "--out", dir + "/squares.png"});
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  for (const char* f : {"squares.png", "squares.object_id.png", "squares.material_id.png", "squares.ids.json"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + f)) << f;
  std::ifstream json(dir + "/squares.ids.json");
  EXPECT_EQ(nlohmann::json::parse(json)["object_id"][1]["name"], "Right");
  EXPECT_EQ(IdsPath("out.d/frame"), "out.d/frame.ids.json");
  EXPECT_EQ(IdsPath("a.exr"), "a.ids.json");
}

}  // namespace
}  // namespace vkpt::internal

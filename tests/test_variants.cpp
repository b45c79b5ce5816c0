// KHR_materials_variants (gltf/gltf_variants.h): --variant NAME|INDEX gives each primitive
// the material its mappings list for that variant, every other primitive keeps its own;
// -v lists the variants; a malformed mapping or an unknown variant is an error naming the
// file and the problem. On the shoe of ../shared/gltf-ext, each variant renders its colour.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cpu/path_tracer.h"
#include "gltf/gltf_loader.h"
#include "gltf_builder.h"
#include "render/render_scene.h"
#include "test_util.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

using namespace test;

// Two triangles: the first maps material 1 in variant 0 ("red") and material 2 in variant
// 2 ("green"), the second has no mappings. Materials: 0 grey, 1 red, 2 green.
GltfBuilder VariantModel(const std::string& firstMappings = R"([{"material":1,"variants":[0]},)"
                                                            R"({"material":2,"variants":[2]}])") {
  GltfBuilder b;
  const int first = b.Positions(kUnitTriangle);
  const int second = b.Positions({{2, 0, 0}, {3, 0, 0}, {2, 1, 0}});
  b.materials = {R"({"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.5,0.5,1]}})",
                 R"({"pbrMetallicRoughness":{"baseColorFactor":[1,0,0,1]}})",
                 R"({"pbrMetallicRoughness":{"baseColorFactor":[0,1,0,1]}})"};
  b.Mesh(first, -1, 0);
  b.meshes.back().insert(b.meshes.back().rfind("}]"),
                         R"(,"extensions":{"KHR_materials_variants":{"mappings":)" + firstMappings + "}}");
  b.Mesh(second, -1, 0);
  b.Node(R"({"mesh":0})");
  b.Node(R"({"mesh":1})");
  b.scenes = {R"({"nodes":[0,1]})"};
  b.extensionsUsed = b.extensionsRequired = {"KHR_materials_variants"};
  b.extraTopLevel +=
      R"(,"extensions":{"KHR_materials_variants":{"variants":[{"name":"red"},{"name":"blue"},{"name":"green"}]}})";
  return b;
}

// The materials of the scene's triangles, in order (one triangle per mesh here).
std::vector<uint32_t> TriangleMaterials(const Scene& s) {
  std::vector<uint32_t> m;
  for (const auto& t : s.triangles) m.push_back(t.material);
  return m;
}

TEST(Variants, EachVariantGivesItsMappedMaterials) {
  const TempFile f(VariantModel().Json());
  const Scene plain = LoadGltf(f.path);
  EXPECT_EQ(plain.materialVariants, (std::vector<std::string>{"red", "blue", "green"}));
  EXPECT_EQ(plain.variant, -1);
  EXPECT_EQ(TriangleMaterials(plain), (std::vector<uint32_t>{0, 0}));
  EXPECT_EQ(TriangleMaterials(LoadGltf(f.path, {}, {.variant = "red"})), (std::vector<uint32_t>{1, 0}));
  EXPECT_EQ(TriangleMaterials(LoadGltf(f.path, {}, {.variant = "2"})), (std::vector<uint32_t>{2, 0}));
  const Scene blue = LoadGltf(f.path, {}, {.variant = "blue"});  // mapped by no primitive
  EXPECT_EQ(blue.variant, 1);
  EXPECT_EQ(TriangleMaterials(blue), (std::vector<uint32_t>{0, 0}));
  for (const std::string& ig : plain.ignoredFeatures) EXPECT_EQ(ig.find("variants"), std::string::npos) << ig;
}

TEST(Variants, UnknownVariantsAndBadMappingsAreNamed) {
  const TempFile f(VariantModel().Json());
  for (const char* wanted : {"purple", "3", "-1"}) {
    try {
      LoadGltf(f.path, {}, {.variant = wanted});
      ADD_FAILURE() << wanted << " loaded";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("--variant ") + wanted +
                                           ": the file has no such material "
                                           "variant; it has 0 \"red\", 1 \"blue\", 2 \"green\""),
                std::string::npos)
          << e.what();
    }
  }
  struct Bad {
    const char* mappings;
    const char* message;
  };
  const Bad bad[] = {
      {R"([{"material":7,"variants":[0]}])", "mappings[0].material is not an index below 3"},
      {R"([{"material":1,"variants":[5]}])", "mappings[0].variants[0] is not an index below 3"},
      {R"([{"material":1}])", "mappings[0] needs a material and an array of variants"},
      {R"({"material":1})", "mappings is missing or not an array"},
  };
  for (const Bad& b : bad) {
    const TempFile bf(VariantModel(b.mappings).Json());
    EXPECT_TRUE(LoadFailsWith(bf.path, {"meshes[0].primitives[0].extensions.KHR_materials_variants.", b.message}));
  }
  GltfBuilder none;
  none.Mesh(none.Positions(kUnitTriangle));
  none.Node(R"({"mesh":0})");
  const TempFile nf(none.Json());
  try {
    LoadGltf(nf.path, {}, {.variant = "red"});
    ADD_FAILURE() << "a file without variants took --variant";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the file has no material variants"), std::string::npos) << e.what();
  }
}

TEST(Variants, CommandLineListsAndRendersThem) {
  const TempFolder dir("variants-cli");
  const std::string model = dir / "v.gltf";
  std::FILE* out = std::fopen(model.c_str(), "w");
  ASSERT_TRUE(out);
  const std::string json = VariantModel().Json();
  std::fwrite(json.data(), 1, json.size(), out);
  std::fclose(out);
  ProcessResult r = RunVkpt({"--scene", model, "--backend", "cpu", "--width", "8", "--spp", "1", "--variant", "green",
                             "-v", "--out", dir / "v.png", "--stats", dir / "v.json"});
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_NE(ReadFile(dir / "v.json").find(R"("material_variant":"green")"), std::string::npos)
      << ReadFile(dir / "v.json");
  EXPECT_NE(r.out.find(R"(material variants (--variant NAME|INDEX): 0 "red", 1 "blue", 2 "green"; rendering "green")"),
            std::string::npos)
      << r.out;
  r = RunVkpt({"--scene", model, "--backend", "cpu", "--variant", "teal", "--out", dir / "w.png"});
  EXPECT_TRUE(r.ExitedWith(1)) << r.Describe();
  EXPECT_NE(r.err.find("--variant teal: the file has no such material variant"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "w.png"));
}

// The shoe's three variants (midnight, beach, street) change its base colour texture:
// three renders of mean colours apart, each unlike the default's where it differs.
TEST(Variants, ShoeRendersEachVariantInItsColours) {
  VKPT_REQUIRE_SHARED_DATA();
  const std::string path = SharedData("gltf-ext/MaterialsVariantsShoe/glTF/MaterialsVariantsShoe.gltf");
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  std::vector<glm::dvec3> means;
  for (const char* v : {"midnight", "beach", "street"}) {
    const Scene s = LoadGltf(path, {}, {.variant = v});
    const RenderScene rs = PrepareRenderScene(s);
    shader::FrameParams p = MakeFrameParams(rs, s.cameras.empty() ? DefaultCamera(s.bounds) : s.cameras[0], 32, 32);
    p.sampleCount = 16;
    p.maxDepth = 8;
    p.rrDepth = 3;
    p.background = glm::vec3(1.0f);
    const Image img = RenderCpu(rs, p).image;
    glm::dvec3 mean(0.0);
    for (const glm::vec3& px : img.pixels) mean += glm::dvec3(px);
    means.push_back(mean / double(img.pixels.size()));
    std::printf("shoe, variant %-8s mean (%.4f, %.4f, %.4f)\n", v, means.back().x, means.back().y, means.back().z);
  }
  for (size_t a = 0; a < means.size(); ++a)
    for (size_t b = a + 1; b < means.size(); ++b)
      EXPECT_GT(glm::length(means[a] - means[b]), 0.01) << "variants " << a << " and " << b << " look alike";
}

}  // namespace
}  // namespace vkpt::internal

// EXT_mesh_gpu_instancing (gltf/gltf_gpu_instancing.h): a node draws its mesh once per
// instance, placed by the instance's TRANSLATION, ROTATION and SCALE and then by the node;
// the instances count against --max-memory before anything is decoded; malformed
// attributes are errors naming the node. SimpleInstancing of ../shared/gltf-ext draws its
// 125 cubes with nothing ignored.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gltf/gltf_loader.h"
#include "gltf_builder.h"

namespace vkpt::internal {
namespace {

using namespace test;

// The unit triangle on nodes[0] (translated to z = 5), drawn by two instances: the first
// in place, the second moved to x = 2, turned 90° about z and doubled.
GltfBuilder TwoInstances(const std::string& rotationAccessor = "") {
  GltfBuilder b = TriangleModel();
  const int t = b.Accessor(b.View(Bytes(std::vector<float>{0, 0, 0, 2, 0, 0})), kFloat, 2, "VEC3");
  const float h = float(std::sqrt(0.5));
  const int r = b.Accessor(b.View(Bytes(std::vector<float>{0, 0, 0, 1, 0, 0, h, h})), kFloat, 2, "VEC4");
  const int s = b.Accessor(b.View(Bytes(std::vector<float>{1, 1, 1, 2, 2, 2})), kFloat, 2, "VEC3");
  b.Node(R"({"mesh":0,"translation":[0,0,5],"extensions":{"EXT_mesh_gpu_instancing":{"attributes":{"TRANSLATION":)" +
         std::to_string(t) + ",\"ROTATION\":" + (rotationAccessor.empty() ? std::to_string(r) : rotationAccessor) +
         ",\"SCALE\":" + std::to_string(s) + "}}}}");
  b.extensionsUsed = b.extensionsRequired = {"EXT_mesh_gpu_instancing"};
  return b;
}

TEST(MeshInstancing, EachInstanceIsPlacedThenTheNode) {
  const Scene s = Load(TwoInstances());
  ASSERT_EQ(s.triangles.size(), 2u);
  EXPECT_TRUE(Near(s.triangles[0].v1, {1, 0, 5}));
  EXPECT_TRUE(Near(s.triangles[0].v2, {0, 1, 5}));
  // (1, 0, 0) doubled and turned to (0, 2, 0), then moved to x = 2; (0, 1, 0) to (−2, 0, 0).
  EXPECT_TRUE(Near(s.triangles[1].v0, {2, 0, 5}));
  EXPECT_TRUE(Near(s.triangles[1].v1, {2, 2, 5}));
  EXPECT_TRUE(Near(s.triangles[1].v2, {0, 0, 5}));
  EXPECT_TRUE(s.ignoredFeatures.empty()) << s.ignoredFeatures.front();
}

TEST(MeshInstancing, MalformedAttributesAreNamed) {
  EXPECT_TRUE(FailsWith(TwoInstances("0"), {"nodes[0].extensions.EXT_mesh_gpu_instancing.attributes.ROTATION has 3 "
                                            "elements, the other attributes 2"}));
  GltfBuilder b = TwoInstances("1");  // the translations: a VEC3
  EXPECT_TRUE(FailsWith(b, {"attributes.ROTATION (accessors[1]) must be a VEC4 of FLOAT or normalized BYTE/SHORT"}));
  b = TwoInstances("9");
  EXPECT_TRUE(FailsWith(b, {"attributes.ROTATION refers to index 9"}));
}

// A thousand instances of a 100,000-triangle mesh are counted as 100 M triangles and
// refused before anything is decoded.
TEST(MeshInstancing, InstancesCountAgainstTheMemoryBudget) {
  GltfBuilder b;
  const int pos = b.Accessor(-1, kFloat, 300000, "VEC3");
  b.Mesh(pos);
  const int t = b.Accessor(-1, kFloat, 1000, "VEC3");
  b.Node(R"({"mesh":0,"extensions":{"EXT_mesh_gpu_instancing":{"attributes":{"TRANSLATION":)" + std::to_string(t) +
         "}}}}");
  b.extensionsUsed = {"EXT_mesh_gpu_instancing"};
  EXPECT_TRUE(FailsWith(b, {"meshes[0] (100000 triangles × 1000 instances = 100000000 triangles)", "--max-memory"}));
}

TEST(MeshInstancing, SimpleInstancingDrawsEveryCube) {
  VKPT_REQUIRE_SHARED_DATA();
  const Scene s = LoadGltf(SharedData("gltf-ext/SimpleInstancing/glTF-Binary/SimpleInstancing.glb"));
  EXPECT_EQ(s.triangles.size(), 1500u);  // 125 instances × 12 triangles (MANIFEST.md)
  EXPECT_TRUE(s.ignoredFeatures.empty()) << s.ignoredFeatures.front();
  std::printf("SimpleInstancing: %zu triangles, bounds (%.3g, %.3g, %.3g) .. (%.3g, %.3g, %.3g)\n", s.triangles.size(),
              s.bounds.lo.x, s.bounds.lo.y, s.bounds.lo.z, s.bounds.hi.x, s.bounds.hi.y, s.bounds.hi.z);
}

}  // namespace
}  // namespace vkpt::internal

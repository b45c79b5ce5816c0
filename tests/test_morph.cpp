// Morph targets (gltf/gltf_meshes.h Morphed, gltf/node_pose.h): a hand-made quad with
// two targets takes exactly base + Σ wᵢ·Δᵢ for its positions and normals, with the mesh's
// weights, the node's (which win), animated weights at chosen times, and a sparse target;
// malformed targets and weights are errors naming the object.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gltf/gltf_loader.h"
#include "gltf_builder.h"

namespace vkpt::internal {
namespace {

using namespace test;

// The unit quad in the xy plane, NORMALs +z. Target 0 lifts vertex 2 by (0, 0, 1) and
// tilts its normal by (1, 0, 0); target 1 moves vertex 1 by (2, 0, 0) (a sparse accessor
// when `sparse`). Mesh weights `meshWeights` ("" for none); nodes[0] `node`. Animation 0
// ("pulse") drives the weights LINEAR from (0, 0) at 1 s to (1, 0.5) at 3 s.
GltfBuilder Quad(const std::string& meshWeights, const std::string& node = R"({"mesh":0})", bool sparse = false) {
  GltfBuilder b;
  const int pos = b.Positions({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  const std::vector<glm::vec3> up(4, glm::vec3(0, 0, 1));
  const int nrm = b.Accessor(b.View(Bytes(up)), kFloat, 4, "VEC3");
  const std::vector<glm::vec3> lift = {{0, 0, 0}, {0, 0, 0}, {0, 0, 1}, {0, 0, 0}};
  const std::vector<glm::vec3> tilt = {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 0, 0}};
  const int t0p = b.Accessor(b.View(Bytes(lift)), kFloat, 4, "VEC3");
  const int t0n = b.Accessor(b.View(Bytes(tilt)), kFloat, 4, "VEC3");
  int t1p;
  if (sparse) {
    const int indices = b.View(Bytes(std::vector<uint16_t>{1})),
              values = b.View(Bytes(std::vector<glm::vec3>{{2, 0, 0}}));
    t1p = b.Accessor(-1, kFloat, 4, "VEC3",
                     R"(,"sparse":{"count":1,"indices":{"bufferView":)" + std::to_string(indices) +
                         R"(,"componentType":5123},"values":{"bufferView":)" + std::to_string(values) + "}}");
  } else {
    t1p = b.Accessor(b.View(Bytes(std::vector<glm::vec3>{{0, 0, 0}, {2, 0, 0}, {0, 0, 0}, {0, 0, 0}})), kFloat, 4,
                     "VEC3");
  }
  const int idx = b.Indices({0, 1, 2, 0, 2, 3});
  b.meshes.push_back(R"({"primitives":[{"attributes":{"POSITION":)" + std::to_string(pos) + ",\"NORMAL\":" +
                     std::to_string(nrm) + "},\"indices\":" + std::to_string(idx) + R"(,"targets":[{"POSITION":)" +
                     std::to_string(t0p) + ",\"NORMAL\":" + std::to_string(t0n) + R"(},{"POSITION":)" +
                     std::to_string(t1p) + "}]}]" + (meshWeights.empty() ? "" : ",\"weights\":" + meshWeights) + "}");
  b.Node(node);
  const std::vector<float> times = {1, 3}, weights = {0, 0, 1, 0.5f};
  const int in = b.Accessor(b.View(Bytes(times)), kFloat, 2, "SCALAR", ",\"min\":[1],\"max\":[3]");
  const int out = b.Accessor(b.View(Bytes(weights)), kFloat, 4, "SCALAR");
  b.animations = {R"({"name":"pulse","samplers":[{"input":)" + std::to_string(in) + ",\"output\":" +
                  std::to_string(out) + R"(}],"channels":[{"sampler":0,"target":{"node":0,"path":"weights"}}]})"};
  return b;
}

// Checks the quad's four corners against base + w0·Δ0 + w1·Δ1, and vertex 2's normal
// against normalize((0, 0, 1) + w0·(1, 0, 0)).
void ExpectMorphed(const Scene& s, float w0, float w1) {
  ASSERT_EQ(s.triangles.size(), 2u);
  const glm::vec3 v0(0, 0, 0), v1(1 + 2 * w1, 0, 0), v2(1, 1, w0), v3(0, 1, 0);
  EXPECT_TRUE(Near(s.triangles[0].v0, v0, 0.0f));
  EXPECT_TRUE(Near(s.triangles[0].v1, v1, 0.0f));
  EXPECT_TRUE(Near(s.triangles[0].v2, v2, 0.0f));
  EXPECT_TRUE(Near(s.triangles[1].v2, v3, 0.0f));
  EXPECT_TRUE(Near(s.normals[0].n2, glm::normalize(glm::vec3(w0, 0, 1)), 1e-7f));
  EXPECT_TRUE(Near(s.normals[0].n0, glm::vec3(0, 0, 1), 0.0f));
}

TEST(Morph, MeshWeightsDisplaceExactly) {
  ExpectMorphed(Load(Quad("[0.25,0.5]")), 0.25f, 0.5f);
  ExpectMorphed(Load(Quad("")), 0.0f, 0.0f);  // no weights: the base mesh
}

TEST(Morph, NodeWeightsOverrideTheMeshs) {
  ExpectMorphed(Load(Quad("[0.25,0.5]", R"({"mesh":0,"weights":[1,0.75]})")), 1.0f, 0.75f);
}

TEST(Morph, SparseTargetsDisplaceOnlyTheirVertices) {
  ExpectMorphed(Load(Quad("[0.25,0.5]", R"({"mesh":0})", true)), 0.25f, 0.5f);
}

TEST(Morph, AnimatedWeightsAtChosenTimes) {
  // Before the first key, its value; between, linear; after the last, its value.
  const std::pair<double, glm::vec2> cases[] = {{0.0, {0, 0}},        {1.0, {0, 0}},    {1.5, {0.25f, 0.125f}},
                                                {2.0, {0.5f, 0.25f}}, {3.0, {1, 0.5f}}, {9.0, {1, 0.5f}}};
  for (const auto& [t, w] : cases) {
    SCOPED_TRACE("at " + std::to_string(t) + " s");
    ExpectMorphed(Load(Quad("[0.25,0.5]"), {.animation = "pulse", .time = t}), w.x, w.y);
  }
}

TEST(Morph, MalformedTargetsAndWeightsAreNamed) {
  EXPECT_TRUE(FailsWith(Quad("[0.25]"), {"meshes[0].weights has 1 weights, but the mesh has 2 morph targets"}));
  EXPECT_TRUE(FailsWith(Quad("", R"({"mesh":0,"weights":[1,2,3]})"),
                        {"nodes[0].weights has 3 weights, but the mesh has 2 morph targets"}));
  GltfBuilder b = Quad("");
  std::string& mesh = b.meshes[0];
  mesh.replace(mesh.find(R"({"POSITION":2,)"), std::string(R"({"POSITION":2,)").size(), R"({"POSITION":5,)");
  EXPECT_TRUE(FailsWith(b, {"meshes[0].primitives[0].targets[0].POSITION (accessors[5])", "VEC3"}));
  b = Quad("");
  b.meshes[0].replace(b.meshes[0].find("}]}]"), 4, R"(}]},{"attributes":{"POSITION":0},"indices":5}])");
  EXPECT_TRUE(FailsWith(b, {"meshes[0].primitives[1] has 0 morph targets, but primitives[0] has 2"}));
}

}  // namespace
}  // namespace vkpt::internal

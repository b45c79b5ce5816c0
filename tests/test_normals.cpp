// Vertex normals: glTF NORMAL through the loader (transforms, mirroring, validation) into
// the RenderScene's octahedrally encoded TriangleShading records.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gltf_builder.h"
#include "render/octahedral.h"
#include "render/render_scene.h"
#include "shared/shading_normal.h"

namespace vkpt::internal {
namespace {

using namespace test;

// A FLOAT VEC3 accessor of `normals` (not necessarily unit length).
int Normals(GltfBuilder& b, const std::vector<glm::vec3>& normals) {
  return b.Accessor(b.View(Bytes(normals)), kFloat, normals.size(), "VEC3");
}

// Mesh `b.meshes.size()`: one primitive with POSITION and NORMAL accessors.
int MeshWithNormals(GltfBuilder& b, int positions, int normals) {
  b.meshes.push_back(R"({"primitives":[{"attributes":{"POSITION":)" + std::to_string(positions) + R"(,"NORMAL":)" +
                     std::to_string(normals) + "}}]}");
  return int(b.meshes.size()) - 1;
}

// The unit triangle with the given vertex normals, under one node with `nodeFields`.
GltfBuilder NormalModel(const std::vector<glm::vec3>& normals, const std::string& nodeFields = "") {
  GltfBuilder b;
  MeshWithNormals(b, b.Positions(kUnitTriangle), Normals(b, normals));
  b.Node(R"({"mesh":0)" + nodeFields + "}");
  return b;
}

TEST(Normals, NonUniformScaleUsesInverseTranspose) {
  const float r2 = std::sqrt(0.5f);
  Scene s = Load(NormalModel({{r2, r2, 0}, {0, 0, 1}, {r2, 0, r2}}, R"(,"scale":[2,1,1])"));
  ASSERT_EQ(s.normals.size(), 1u);
  const VertexNormals& n = s.normals[0];
  ASSERT_TRUE(n.Present());
  // (M⁻¹)ᵀ = diag(1/2, 1, 1): (1,1,0) → (1/2,1,0) ∝ (1,2,0); (1,0,1) → (1/2,0,1) ∝ (1,0,2).
  const float r5 = 1.0f / std::sqrt(5.0f);
  EXPECT_TRUE(Near(n.n0, {r5, 2 * r5, 0}));
  EXPECT_TRUE(Near(n.n1, {0, 0, 1}));
  EXPECT_TRUE(Near(n.n2, {r5, 0, 2 * r5}));
}

TEST(Normals, StayPerpendicularToTheTransformedSurface) {
  // The plane x + z = 0 with its own normal, sheared and scaled by a node matrix.
  GltfBuilder b;
  const glm::vec3 n = glm::normalize(glm::vec3(1, 0, 1));
  MeshWithNormals(b, b.Positions({{0, 0, 0}, {1, 0, -1}, {0, 1, 0}}), Normals(b, {n, n, n}));
  b.Node(R"({"mesh":0,"matrix":[3,0,0,0, 1,1,0,0, 0,2,0.5,0, 4,5,6,1]})");
  Scene s = Load(b);
  ASSERT_EQ(s.normals.size(), 1u);
  const SceneTriangle& t = s.triangles[0];
  const glm::vec3 geometric = glm::normalize(glm::cross(t.v1 - t.v0, t.v2 - t.v0));
  EXPECT_NEAR(glm::dot(s.normals[0].n0, geometric), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::length(s.normals[0].n2), 1.0f, 1e-6f);
}

TEST(Normals, MirroredNodeKeepsEachNormalWithItsVertex) {
  // Each vertex's normal points the way of its position (the origin's along +Z), so
  // the pairing survives any reordering the mirror's winding fix makes.
  Scene s = Load(NormalModel({{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, R"(,"scale":[-1,1,1])"));
  ASSERT_EQ(s.normals.size(), 1u);
  const SceneTriangle& t = s.triangles[0];
  const VertexNormals& n = s.normals[0];
  EXPECT_TRUE(Near(t.v1, {0, 1, 0})) << "the winding fix swaps v1 and v2";
  EXPECT_TRUE(Near(n.n0, {0, 0, 1}));
  EXPECT_TRUE(Near(n.n1, glm::normalize(t.v1)));
  EXPECT_TRUE(Near(n.n2, glm::normalize(t.v2)));
  EXPECT_TRUE(Near(n.n2, {-1, 0, 0}));
}

TEST(Normals, AbsentNormalLeavesTheSceneFlat) {
  GltfBuilder b = TriangleModel();
  b.Node(R"({"mesh":0})");
  Scene s = Load(b);
  EXPECT_TRUE(s.normals.empty());
  RenderScene rs = PrepareRenderScene(s);
  ASSERT_EQ(rs.shading.size(), 1u);
  EXPECT_EQ(rs.shading[0].flags, 0u);
}

TEST(Normals, MeshesWithAndWithoutNormalsMix) {
  for (bool normalsFirst : {false, true}) {
    GltfBuilder b = TriangleModel();  // mesh 0: no normals
    MeshWithNormals(b, b.Positions(kUnitTriangle), Normals(b, {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}));
    b.Node(normalsFirst ? R"({"children":[2,1]})" : R"({"children":[1,2]})");
    b.Node(R"({"mesh":0})");
    b.Node(R"({"mesh":1})");
    Scene s = Load(b);
    ASSERT_EQ(s.triangles.size(), 2u);
    ASSERT_EQ(s.normals.size(), 2u);
    EXPECT_EQ(s.normals[0].Present(), normalsFirst);
    EXPECT_EQ(s.normals[1].Present(), !normalsFirst);
  }
}

TEST(Normals, VanishingNormalFallsBackToFlat) {
  {  // a zero normal in the file
    Scene s = Load(NormalModel({{0, 0, 1}, {0, 0, 0}, {0, 0, 1}}));
    EXPECT_TRUE(s.normals.empty());
  }
  {  // a singular transform (scale 0 along the normals)
    Scene s = Load(NormalModel({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}, R"(,"scale":[1,1,0])"));
    ASSERT_EQ(s.triangles.size(), 1u);
    EXPECT_TRUE(s.normals.empty());
  }
}

TEST(Normals, QuantizedNormalsWithKhrMeshQuantization) {
  GltfBuilder b;
  // Normalized BYTE VEC3, padded to 4 bytes per element as the extension requires.
  std::vector<int8_t> q = {0, 0, 127, 0, 127, 0, 0, 0, 0, -127, 0, 0};
  int normals = b.Accessor(b.View(Bytes(q), 4), kByte, 3, "VEC3", R"(,"normalized":true)");
  MeshWithNormals(b, b.Positions(kUnitTriangle), normals);
  b.Node(R"({"mesh":0})");
  EXPECT_TRUE(FailsWith(b, {"meshes[0].primitives[0].attributes.NORMAL", "FLOAT VEC3"}));
  b.extensionsUsed = {"KHR_mesh_quantization"};
  Scene s = Load(b);
  ASSERT_EQ(s.normals.size(), 1u);
  EXPECT_TRUE(Near(s.normals[0].n0, {0, 0, 1}));
  EXPECT_TRUE(Near(s.normals[0].n1, {1, 0, 0}));
  EXPECT_TRUE(Near(s.normals[0].n2, {0, -1, 0}));
}

TEST(Normals, InvalidAccessorsAreNamed) {
  const std::string where = "meshes[0].primitives[0].attributes.NORMAL";
  {  // wrong type
    GltfBuilder b;
    std::vector<glm::vec2> n(3, glm::vec2(0, 1));
    MeshWithNormals(b, b.Positions(kUnitTriangle), b.Accessor(b.View(Bytes(n)), kFloat, 3, "VEC2"));
    b.Node(R"({"mesh":0})");
    EXPECT_TRUE(FailsWith(b, {where, "FLOAT VEC3"}));
  }
  {  // wrong count
    GltfBuilder b;
    MeshWithNormals(b, b.Positions(kUnitTriangle), Normals(b, {{0, 0, 1}, {0, 0, 1}}));
    b.Node(R"({"mesh":0})");
    EXPECT_TRUE(FailsWith(b, {where, "2 elements but POSITION has 3"}));
  }
  {  // NaN
    EXPECT_TRUE(
        FailsWith(NormalModel({{0, 0, 1}, {NAN, 0, 1}, {0, 0, 1}}), {where, "element 1", "not a finite normal"}));
  }
}

// ---------------------------------------------------------------------------------------
// Octahedral encoding

float AngleBetween(glm::vec3 a, glm::vec3 b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));  // accurate near 0
}

TEST(Octahedral, RoundTripErrorIsTiny) {
  std::mt19937 rng(7);
  std::normal_distribution<float> gauss;
  float worst = 0.0f;
  for (int i = 0; i < 200000; ++i) {
    glm::vec3 n = glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)));
    worst = std::max(worst, AngleBetween(shader::DecodeOctahedral(EncodeOctahedral(n)), n));
  }
  RecordProperty("max_error_rad", std::to_string(worst));
  EXPECT_LT(worst, 1e-4f);
}

TEST(Octahedral, AxesAreExact) {
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {1.0f, -1.0f}) {
      glm::vec3 n(0.0f);
      n[axis] = sign;
      EXPECT_EQ(shader::DecodeOctahedral(EncodeOctahedral(n)), n) << "axis " << axis << " sign " << sign;
    }
}

TEST(Octahedral, InterpolatedNormalBlendsVertexNormals) {
  const glm::vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  shader::TriangleShading s{EncodeOctahedral(x), EncodeOctahedral(y), EncodeOctahedral(z), shader::kShadingHasNormals};
  EXPECT_TRUE(Near(shader::InterpolatedNormal(s, 0, 0), x));
  EXPECT_TRUE(Near(shader::InterpolatedNormal(s, 1, 0), y));
  EXPECT_TRUE(Near(shader::InterpolatedNormal(s, 0, 1), z));
  EXPECT_TRUE(Near(shader::InterpolatedNormal(s, 0.5f, 0), glm::normalize(x + y)));
  EXPECT_TRUE(Near(shader::InterpolatedNormal(s, 1 / 3.0f, 1 / 3.0f), glm::normalize(x + y + z)));
}

TEST(Octahedral, RenderSceneShadingIsIndexedBySourceTriangle) {
  // Triangle 0 is degenerate (dropped from the BVH) but keeps its shading slot.
  GltfBuilder b;
  MeshWithNormals(b, b.Positions({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}}),
                  Normals(b, {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0}, {0, 0, -1}}));
  b.Node(R"({"mesh":0})");
  Scene s = Load(b);
  ASSERT_EQ(s.triangles.size(), 2u);
  ASSERT_EQ(s.normals.size(), 2u);
  EXPECT_TRUE(s.normals[0].Present());
  RenderScene rs = PrepareRenderScene(s);
  ASSERT_EQ(rs.triangles.size(), 1u);
  ASSERT_EQ(rs.shading.size(), 2u);
  EXPECT_EQ(rs.shading[0].flags, shader::kShadingHasNormals);
  const shader::TriangleShading& sh = rs.shading[rs.triangles[0].sourceIndex];
  EXPECT_EQ(sh.flags, shader::kShadingHasNormals);
  EXPECT_EQ(shader::DecodeOctahedral(sh.n1), glm::vec3(0, 1, 0));
  EXPECT_EQ(shader::DecodeOctahedral(sh.n2), glm::vec3(0, 0, -1));
}

TEST(Octahedral, FlatShadedTrianglesDropTheirNormals) {
  // Triangle 0's vertex normals are its face normal (+z): it renders flat, without them.
  // Triangle 1's point the other way, so they must stay (the shader faces them forward).
  GltfBuilder b;
  MeshWithNormals(b, b.Positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}}),
                  Normals(b, {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, -1}, {0, 0, -1}, {0, 0, -1}}));
  b.Node(R"({"mesh":0})");
  RenderScene rs = PrepareRenderScene(Load(b));
  ASSERT_EQ(rs.shading.size(), 2u);
  EXPECT_EQ(rs.shading[0].flags, 0u);
  EXPECT_EQ(rs.shading[1].flags, shader::kShadingHasNormals);
}

}  // namespace
}  // namespace vkpt::internal

// Skins (gltf/gltf_skins.h, gltf/posed_primitive.h): a hand-made two-bone bar bent at
// its middle joint, whose skinned vertices have a closed form — positions to 1e-5 for every
// encoding of JOINTS_n/WEIGHTS_n the spec allows, normals by the blended matrices' inverse
// transpose, the skinned mesh's own node transform ignored, a joint's animation followed;
// the same file without its inverse bind matrices (the loader ignoring them) misses the
// closed form; malformed skins are errors naming the object.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "gltf/gltf_loader.h"
#include "gltf_builder.h"

namespace vkpt::internal {
namespace {

using namespace test;

constexpr double kPi = 3.14159265358979323846;

// How the bar's skin attributes are stored.
enum class Encoding {
  kFloatWeights,       // JOINTS_0 UNSIGNED_BYTE, WEIGHTS_0 FLOAT
  kNormalizedWeights,  // JOINTS_0 UNSIGNED_SHORT, WEIGHTS_0 normalized UNSIGNED_BYTE
  kUnnormalized,       // FLOAT weights summing to 2, which the loader scales to 1
  kTwoSets,            // the middle vertices' second joint in JOINTS_1/WEIGHTS_1
};

// The bar's nodes, skin and animation (Bar says which).
void AddArmature(GltfBuilder& b, double bend, bool inverseBinds) {
  const std::string q = "[0,0," + Num(std::sin(bend / 2)) + "," + Num(std::cos(bend / 2)) + "]";
  b.Node(R"({"translation":[5,0,0],"children":[1]})");
  b.Node(R"({"children":[2]})");
  b.Node(R"({"translation":[1,0,0],"rotation":)" + q + "}");
  b.Node(R"({"mesh":0,"skin":0,"translation":[100,0,0],"scale":[3,3,3]})");
  b.scenes = {R"({"nodes":[0,3]})"};
  std::string skin = R"({"joints":[1,2])";
  if (inverseBinds) {
    const std::vector<float> ibm = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0,  0, 0, 1,   // joint 0: identity
                                    1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 1};  // joint 1: T(−1, 0, 0)
    skin += ",\"inverseBindMatrices\":" + std::to_string(b.Accessor(b.View(Bytes(ibm)), kFloat, 2, "MAT4"));
  }
  b.skins = {skin + "}"};
  const std::vector<float> times = {0, 1},
                           turns = {0, 0, 0, 1, 0, 0, float(std::sin(kPi / 4)), float(std::cos(kPi / 4))};
  const int in = b.Accessor(b.View(Bytes(times)), kFloat, 2, "SCALAR", ",\"min\":[0],\"max\":[1]");
  const int out = b.Accessor(b.View(Bytes(turns)), kFloat, 2, "VEC4");
  b.animations = {R"({"name":"bend","samplers":[{"input":)" + std::to_string(in) + ",\"output\":" +
                  std::to_string(out) + R"(}],"channels":[{"sampler":0,"target":{"node":2,"path":"rotation"}}]})"};
}

// The bar: x ∈ {0, 0.5, 1, 1.5, 2} × y ∈ {0, 0.2} in the xy plane, NORMALs along +x (so
// that bending about z turns them). Vertices at x < 1 follow joint 0, at x > 1 joint 1,
// at x = 1 half each. Joint 0 is nodes[1] at the origin of the armature root nodes[0]
// (translated to x = 5); joint 1 is nodes[2], one unit along x, turned by `bend` radians
// about z. The skinned mesh node, nodes[3], has a transform of its own that must not
// apply. Animation 0 turns joint 1 from 0 to 90° over one second (LINEAR).
GltfBuilder Bar(double bend, Encoding enc = Encoding::kFloatWeights, bool inverseBinds = true) {
  GltfBuilder b;
  std::vector<glm::vec3> p, n;
  std::vector<float> w0, w1;
  std::vector<uint8_t> j0, j1;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 2; ++j) {
      p.push_back({0.5f * i, 0.2f * j, 0.0f});
      n.push_back({1, 0, 0});
      const float a = i < 2 ? 1.0f : i == 2 ? 0.5f : 0.0f;  // joint 0's share
      const float scale = enc == Encoding::kUnnormalized ? 2.0f : 1.0f;
      if (enc == Encoding::kTwoSets && i == 2) {
        j0.insert(j0.end(), {0, 0, 0, 0}), w0.insert(w0.end(), {0.5f, 0, 0, 0});
        j1.insert(j1.end(), {1, 0, 0, 0}), w1.insert(w1.end(), {0.5f, 0, 0, 0});
      } else {
        j0.insert(j0.end(), {0, 1, 0, 0}), w0.insert(w0.end(), {scale * a, scale * (1 - a), 0, 0});
        j1.insert(j1.end(), {0, 0, 0, 0}), w1.insert(w1.end(), {0, 0, 0, 0});
      }
    }
  std::vector<uint32_t> idx;
  for (uint32_t i = 0; i < 4; ++i) idx.insert(idx.end(), {2 * i, 2 * i + 2, 2 * i + 3, 2 * i, 2 * i + 3, 2 * i + 1});
  const int pos = b.Positions(p), nrm = b.Accessor(b.View(Bytes(n)), kFloat, n.size(), "VEC3");
  int joints, weights;
  if (enc == Encoding::kNormalizedWeights) {
    std::vector<uint16_t> j16(j0.begin(), j0.end());
    std::vector<uint8_t> w8;
    for (float x : w0) w8.push_back(uint8_t(x == 0.5f ? 128 : x * 255));  // 128/255 each: equal shares
    joints = b.Accessor(b.View(Bytes(j16)), kUShort, p.size(), "VEC4");
    weights = b.Accessor(b.View(Bytes(w8)), kUByte, p.size(), "VEC4", ",\"normalized\":true");
  } else {
    joints = b.Accessor(b.View(Bytes(j0)), kUByte, p.size(), "VEC4");
    weights = b.Accessor(b.View(Bytes(w0)), kFloat, p.size(), "VEC4");
  }
  std::string attributes = "\"POSITION\":" + std::to_string(pos) + ",\"NORMAL\":" + std::to_string(nrm) +
                           ",\"JOINTS_0\":" + std::to_string(joints) + ",\"WEIGHTS_0\":" + std::to_string(weights);
  if (enc == Encoding::kTwoSets)
    attributes += ",\"JOINTS_1\":" + std::to_string(b.Accessor(b.View(Bytes(j1)), kUByte, p.size(), "VEC4")) +
                  ",\"WEIGHTS_1\":" + std::to_string(b.Accessor(b.View(Bytes(w1)), kFloat, p.size(), "VEC4"));
  b.meshes.push_back("{\"primitives\":[{\"attributes\":{" + attributes +
                     "},\"indices\":" + std::to_string(b.Indices(idx)) + "}]}");
  AddArmature(b, bend, inverseBinds);
  return b;
}

// Where linear blend skinning takes the bar's vertex (x, y) when joint 1 is turned by θ:
// joint 0 moves it by the armature's T(5, 0, 0); joint 1 by T(6, 0, 0)·Rz(θ)·T(−1, 0, 0).
glm::dvec3 ExpectedPosition(glm::dvec3 v, double theta) {
  const glm::dvec3 a = v + glm::dvec3(5, 0, 0);
  const glm::dvec3 b(6 + (v.x - 1) * std::cos(theta) - v.y * std::sin(theta),
                     (v.x - 1) * std::sin(theta) + v.y * std::cos(theta), 0);
  return v.x < 1 ? a : v.x > 1 ? b : 0.5 * (a + b);
}

// And its normal, (1, 0, 0) turned by the blend's inverse transpose: by θ on joint 1, by
// θ/2 where the shares are equal (½(I + R(θ)) is cos(θ/2)·R(θ/2)).
glm::dvec3 ExpectedNormal(glm::dvec3 v, double theta) {
  const double phi = v.x < 1 ? 0.0 : v.x > 1 ? theta : theta / 2;
  return {std::cos(phi), std::sin(phi), 0};
}

// The largest distance between the scene's skinned vertices and the closed form at θ,
// positions and normals; the triangles come in the file's order, its corners unswapped.
struct SkinError {
  double position = 0.0, normal = 0.0;
};
SkinError BarError(const Scene& s, double theta) {
  SkinError e;
  const uint32_t idx[4][6] = {{0, 2, 3, 0, 3, 1}, {2, 4, 5, 2, 5, 3}, {4, 6, 7, 4, 7, 5}, {6, 8, 9, 6, 9, 7}};
  for (size_t t = 0; t < s.triangles.size(); ++t)
    for (int c = 0; c < 3; ++c) {
      const uint32_t i = idx[t / 2][(t % 2) * 3 + c];
      const glm::dvec3 bind(0.5 * (i / 2), 0.2 * (i % 2), 0);
      const glm::vec3 got = c == 0 ? s.triangles[t].v0 : c == 1 ? s.triangles[t].v1 : s.triangles[t].v2;
      const glm::vec3 n = c == 0 ? s.normals[t].n0 : c == 1 ? s.normals[t].n1 : s.normals[t].n2;
      e.position = std::max(e.position, glm::length(glm::dvec3(got) - ExpectedPosition(bind, theta)));
      e.normal = std::max(e.normal, glm::length(glm::dvec3(n) - ExpectedNormal(bind, theta)));
    }
  return e;
}

class SkinnedBar : public ::testing::TestWithParam<Encoding> {};

TEST_P(SkinnedBar, MatchesLinearBlendSkinningInClosedForm) {
  for (double theta : {kPi / 2, kPi / 3, -2.0}) {
    const Scene s = Load(Bar(theta, GetParam()));
    ASSERT_EQ(s.triangles.size(), 8u);
    ASSERT_EQ(s.normals.size(), 8u);
    const SkinError e = BarError(s, theta);
    std::printf("bend %.4f rad: worst position error %.3g, normal error %.3g (limit 1e-5)\n", theta, e.position,
                e.normal);
    EXPECT_LT(e.position, 1e-5);
    EXPECT_LT(e.normal, 1e-5);
  }
}

INSTANTIATE_TEST_SUITE_P(Encodings, SkinnedBar,
                         ::testing::Values(Encoding::kFloatWeights, Encoding::kNormalizedWeights,
                                           Encoding::kUnnormalized, Encoding::kTwoSets));

// The loader ignoring the inverse bind matrices is what it does with a file that has
// none: the same bar without them must miss the closed form by far more than the limit.
TEST(Skinning, WithoutInverseBindMatricesTheClosedFormIsMissed) {
  const SkinError e = BarError(Load(Bar(kPi / 2, Encoding::kFloatWeights, false)), kPi / 2);
  std::printf("without inverse bind matrices: worst position error %.3g (the test's limit 1e-5)\n", e.position);
  EXPECT_GT(e.position, 0.5);
}

TEST(Skinning, JointAnimationBendsTheBar) {
  // The rest pose has no bend of its own here: the animation turns joint 1 over 0..90°.
  for (double t : {0.0, 0.25, 0.5, 1.0, 3.0}) {
    const Scene s = Load(Bar(0.0), {.animation = "bend", .time = t});
    const double theta = kPi / 2 * std::min(t, 1.0);
    const SkinError e = BarError(s, theta);
    std::printf("at %.2f s (bend %.4f rad): worst position error %.3g (limit 1e-5)\n", t, theta, e.position);
    EXPECT_LT(e.position, 1e-5);
    EXPECT_LT(e.normal, 1e-5);
  }
}

TEST(Skinning, MalformedSkinsAreNamed) {
  GltfBuilder b = Bar(0.0);
  b.skins = {R"({"joints":[1,7]})"};
  EXPECT_TRUE(FailsWith(b, {"skins[0].joints[1]", "index 7"}));
  b.skins = {R"({"joints":[1,1]})"};
  EXPECT_TRUE(FailsWith(b, {"skins[0].joints lists nodes[1] twice"}));
  b.skins = {R"({"joints":[2]})"};  // the bar's vertices name joint 1 too
  EXPECT_TRUE(FailsWith(b, {"nodes[3] (mesh 0): vertex", "names joint 1, but the skin has 1"}));
  b.skins = {R"({"joints":[1,2],"inverseBindMatrices":0})"};  // accessors[0] is the positions
  EXPECT_TRUE(FailsWith(b, {"skins[0].inverseBindMatrices (accessors[0]) must be a FLOAT MAT4 accessor"}));
  b = Bar(0.0);
  b.nodes[3] = R"({"mesh":0,"skin":4})";
  EXPECT_TRUE(FailsWith(b, {"nodes[3].skin refers to index 4"}));
}

TEST(Skinning, MalformedSkinAttributesAreNamed) {
  GltfBuilder b = Bar(0.0);
  std::string& mesh = b.meshes[0];
  const std::string original = mesh;
  mesh.replace(mesh.find(",\"WEIGHTS_0\""), std::string(",\"WEIGHTS_0\":3").size(), "");
  EXPECT_TRUE(FailsWith(b, {"meshes[0].primitives[0] has one of JOINTS_0 and WEIGHTS_0 without the other"}));
  mesh = original;
  mesh.replace(mesh.find("\"JOINTS_0\":2"), std::string("\"JOINTS_0\":2").size(), "\"JOINTS_0\":3");
  EXPECT_TRUE(FailsWith(b, {"JOINTS_0 (accessors[3]) must be an UNSIGNED_BYTE or UNSIGNED_SHORT VEC4 accessor"}));
  mesh = original;
  mesh.replace(mesh.find("\"WEIGHTS_0\":3"), std::string("\"WEIGHTS_0\":3").size(), "\"WEIGHTS_0\":1");
  EXPECT_TRUE(FailsWith(b, {"WEIGHTS_0 (accessors[1]) must be a VEC4 accessor of FLOAT"}));
}

}  // namespace
}  // namespace vkpt::internal

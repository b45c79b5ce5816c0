// Animation (gltf/keyframes.h, gltf/gltf_animation.h): each interpolation mode before,
// between and after its keyframes against hand-computed values — CUBICSPLINE's tangents
// scaled by the interval, rotations slerped the short way — and through a file:
// --animation by name or index, --at, nodes posed with their children, cameras and
// lights; malformed animations are errors naming the object.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "gltf/gltf_loader.h"
#include "gltf/keyframes.h"
#include "gltf_builder.h"

namespace vkpt::internal {
namespace {

using namespace test;

constexpr double kPi = 3.14159265358979323846;

Keyframes Curve(Interpolation mode, std::vector<double> times, std::vector<double> values, size_t width,
                bool rotation = false) {
  Keyframes k;
  k.times = std::move(times);
  k.values = std::move(values);
  k.width = width;
  k.mode = mode;
  k.rotation = rotation;
  return k;
}

TEST(Keyframes, StepHoldsEachKeyUntilTheNext) {
  const Keyframes k = Curve(Interpolation::kStep, {1, 2, 4}, {10, 20, 40}, 1);
  const std::pair<double, double> cases[] = {{0, 10}, {1, 10}, {1.99, 10}, {2, 20}, {3.9, 20}, {4, 40}, {7, 40}};
  for (const auto& [t, v] : cases) EXPECT_EQ(k.At(t)[0], v) << "at " << t;
}

TEST(Keyframes, LinearInterpolatesComponentwise) {
  const Keyframes k = Curve(Interpolation::kLinear, {1, 3}, {0, 10, -2, 4, 0, 2}, 3);
  EXPECT_EQ(k.At(0), (std::vector<double>{0, 10, -2}));
  EXPECT_EQ(k.At(1.5), (std::vector<double>{1, 7.5, -1}));
  EXPECT_EQ(k.At(2), (std::vector<double>{2, 5, 0}));
  EXPECT_EQ(k.At(5), (std::vector<double>{4, 0, 2}));
}

TEST(Keyframes, CubicSplineScalesTangentsByTheInterval) {
  // Keys at 1 s and 3 s (interval 2): values 0 and 1, out-tangent of key 0 = 3, in-tangent
  // of key 1 = −1 (per second). p(s) = (2s³−3s²+1)·0 + 2(s³−2s²+s)·3 + (−2s³+3s²)·1 + 2(s³−s²)·(−1).
  const Keyframes k = Curve(Interpolation::kCubicSpline, {1, 3}, {9, 0, 3, -1, 1, 9}, 1);
  auto p = [](double s) {
    return 6 * (s * s * s - 2 * s * s + s) + (-2 * s * s * s + 3 * s * s) - 2 * (s * s * s - s * s);
  };
  EXPECT_EQ(k.At(0)[0], 0.0);  // the value, not a tangent
  EXPECT_EQ(k.At(4)[0], 1.0);
  for (double s : {0.1, 0.25, 0.5, 0.9}) EXPECT_NEAR(k.At(1 + 2 * s)[0], p(s), 1e-12) << "s " << s;
  // Tangents left unscaled by the interval would give p(0.5) = 1.
  EXPECT_NEAR(k.At(2)[0], 1.5, 1e-12);
}

TEST(Keyframes, SlerpTakesTheShortWay) {
  // From identity to 90° about z — the second key stored as −q, the same rotation. The
  // short way passes 45° at the middle; the long way would pass −135°.
  const double h = std::sqrt(0.5);
  const Keyframes k = Curve(Interpolation::kLinear, {0, 1}, {0, 0, 0, 1, 0, 0, -h, -h}, 4, true);
  const std::vector<double> q = k.At(0.5);
  const double angle = 2 * std::atan2(q[2], q[3]);
  const double folded = std::remainder(angle, 2 * kPi);  // q and −q: angles 2π apart
  EXPECT_NEAR(std::abs(folded), kPi / 4, 1e-12);
  EXPECT_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1.0, 1e-12);
  // Constant angular speed: a quarter of the way is 22.5°.
  const std::vector<double> r = k.At(0.25);
  EXPECT_NEAR(std::abs(std::remainder(2 * std::atan2(r[2], r[3]), 2 * kPi)), kPi / 8, 1e-12);
}

TEST(Keyframes, CubicRotationsAreRenormalized) {
  const Keyframes k = Curve(Interpolation::kCubicSpline, {0, 1},
                            {0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0}, 4, true);
  const std::vector<double> q = k.At(0.5);
  EXPECT_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1.0, 1e-12);
}

// A triangle under nodes[1], child of nodes[0], which animation "move" (index 0) translates
// with STEP keys (0 → (1,0,0) → (2,0,0) at 0, 1, 2 s) and animation "spin" (index 1) turns
// about z by 0 → 180° LINEAR over 2 s. nodes[1] carries a camera and a point light.
GltfBuilder Animated() {
  GltfBuilder b = TriangleModel();
  b.cameras = {R"({"type":"perspective","perspective":{"yfov":0.8,"znear":0.1}})"};
  b.extensionsUsed = {"KHR_lights_punctual"};
  b.extraTopLevel = R"(,"extensions":{"KHR_lights_punctual":{"lights":[{"type":"point","intensity":1}]}})";
  b.Node(R"({"children":[1]})");
  b.Node(R"({"mesh":0,"camera":0,"translation":[0,0,5],"extensions":{"KHR_lights_punctual":{"light":0}}})");
  const std::vector<float> t3 = {0, 1, 2}, t2 = {0, 2};
  const std::vector<float> moves = {0, 0, 0, 1, 0, 0, 2, 0, 0};
  const std::vector<float> turns = {0, 0, 0, 1, 0, 0, 1, 0};
  const int in3 = b.Accessor(b.View(Bytes(t3)), kFloat, 3, "SCALAR", ",\"min\":[0],\"max\":[2]");
  const int in2 = b.Accessor(b.View(Bytes(t2)), kFloat, 2, "SCALAR", ",\"min\":[0],\"max\":[2]");
  const int move = b.Accessor(b.View(Bytes(moves)), kFloat, 3, "VEC3");
  const int turn = b.Accessor(b.View(Bytes(turns)), kFloat, 2, "VEC4");
  auto animation = [](const std::string& name, int in, int out, const std::string& mode, const std::string& path) {
    return R"({"name":")" + name + R"(","samplers":[{"input":)" + std::to_string(in) +
           ",\"output\":" + std::to_string(out) + R"(,"interpolation":")" + mode +
           R"("}],"channels":[{"sampler":0,"target":{"node":0,"path":")" + path + "\"}}]}";
  };
  b.animations = {animation("move", in3, move, "STEP", "translation"),
                  animation("spin", in2, turn, "LINEAR", "rotation")};
  return b;
}

TEST(Animation, PosesNodesTheirChildrenCamerasAndLights) {
  const Scene rest = Load(Animated());
  EXPECT_TRUE(Near(rest.triangles[0].v1, {1, 0, 5}));
  ASSERT_EQ(rest.animations.size(), 2u);
  EXPECT_EQ(rest.animations[0].name, "move");
  EXPECT_EQ(rest.animations[0].duration, 2.0);
  EXPECT_EQ(rest.animation, -1);

  const Scene moved = Load(Animated(), {.animation = "move", .time = 1.5});  // STEP: key 1
  EXPECT_TRUE(Near(moved.triangles[0].v1, {2, 0, 5}));
  EXPECT_TRUE(Near(moved.cameras[0].position, {1, 0, 5}));
  EXPECT_TRUE(Near(moved.lights[0].position, {1, 0, 5}));
  EXPECT_EQ(moved.animation, 0);

  const Scene spun = Load(Animated(), {.animation = "1", .time = 1.0});  // by index: 90° about z
  EXPECT_TRUE(Near(spun.triangles[0].v1, {0, 1, 5}));
  EXPECT_TRUE(Near(spun.triangles[0].v2, {-1, 0, 5}));
  EXPECT_TRUE(Near(spun.cameras[0].right, {0, 1, 0}));
}

TEST(Animation, MalformedAnimationsAreNamed) {
  EXPECT_TRUE(FailsWith(Animated(), {"--animation walk: the file has no such animation; it has 0 \"move\", 1 \"spin\""},
                        {.animation = "walk"}));
  EXPECT_TRUE(FailsWith(TriangleModel(), {"--animation 0: the file has no animations"}, {.animation = "0"}));
  GltfBuilder b = Animated();
  b.nodes[0] = R"({"children":[1],"matrix":[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1]})";
  EXPECT_TRUE(FailsWith(b, {"animations[0].channels[0] animates nodes[0], which has a matrix"}, {.animation = "move"}));
  b = Animated();
  b.animations[0].replace(b.animations[0].find("\"STEP\""), 6, "\"SMOOTH\"");
  EXPECT_TRUE(FailsWith(b, {"animations[0].samplers[0].interpolation \"SMOOTH\" is not LINEAR, STEP or CUBICSPLINE"},
                        {.animation = "move"}));
  b = Animated();
  b.animations[0].replace(b.animations[0].find("\"STEP\""), 6, "\"CUBICSPLINE\"");
  EXPECT_TRUE(FailsWith(b, {"animations[0].samplers[0].output (accessors[3]) has 3 elements; 3 keyframes", "need 9"},
                        {.animation = "move"}));
  b = Animated();
  b.animations[0].replace(b.animations[0].find("\"translation\""), 13, "\"weights\"");
  EXPECT_TRUE(
      FailsWith(b, {"animates the morph weights of nodes[0], whose mesh has no morph targets"}, {.animation = "move"}));
  b = Animated();
  b.animations[1].replace(b.animations[1].find("\"input\":2"), 9, "\"input\":4");  // the rotations: not times
  EXPECT_TRUE(FailsWith(b, {"animations[1].samplers[0].input (accessors[4]) must be a FLOAT SCALAR accessor"}));
}

TEST(Animation, TimesMustIncrease) {
  GltfBuilder b = TriangleModel();
  b.Node(R"({"mesh":0})");
  const int in = b.Accessor(b.View(Bytes(std::vector<float>{0, 2, 1})), kFloat, 3, "SCALAR");
  const int out = b.Accessor(b.View(Bytes(std::vector<float>(9, 0.0f))), kFloat, 3, "VEC3");
  b.animations = {R"({"samplers":[{"input":)" + std::to_string(in) + ",\"output\":" + std::to_string(out) +
                  R"(}],"channels":[{"sampler":0,"target":{"node":0,"path":"scale"}}]})"};
  EXPECT_TRUE(FailsWith(b, {"animations[0].samplers[0].input (accessors[1]) element 2 does not follow element 1"}));
}

// From the command line: -v lists the animations and the pose, --stats records it; --at
// without --animation is a usage error; an unknown animation fails naming the file, with
// nothing written.
TEST(Animation, CommandLinePosesAndReports) {
  const TempFile model(Animated().Json());
  const std::string out = TempPath("animation-cli.pfm"), stats = TempPath("animation-cli.json");
  ProcessResult r = RunVkpt({"--scene", model.path, "--backend", "cpu", "--width", "8", "--height", "8", "--spp", "1",
                             "--out", out, "--stats", stats, "--animation", "move", "--at", "1.5", "-v"});
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_NE(r.out.find("animations (--animation NAME|INDEX, --at SECONDS): 0 \"move\" 2 s, 1 \"spin\" 2 s; "
                       "posing 0 at 1.5 s"),
            std::string::npos)
      << r.out;
  const std::string json = ReadFile(stats);
  EXPECT_NE(json.find("\"animation\":\"move\",\"animation_time\":1.5}"), std::string::npos) << json;
  std::remove(out.c_str());
  std::remove(stats.c_str());

  r = RunVkpt({"--scene", model.path, "--out", out, "--at", "1"});
  EXPECT_TRUE(r.ExitedWith(2)) << r.Describe();
  EXPECT_NE(r.err.find("--at needs --animation: it is a time in that animation"), std::string::npos) << r.err;
  r = RunVkpt({"--scene", model.path, "--out", out, "--animation", "walk"});
  EXPECT_TRUE(r.ExitedWith(1)) << r.Describe();
  EXPECT_NE(r.err.find(model.path + ": --animation walk: the file has no such animation"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// The farthest any triangle corner of `a` lies from its place in `b` (the same mesh).
float LargestMove(const Scene& a, const Scene& b) {
  float d = 0.0f;
  for (size_t t = 0; t < a.triangles.size(); ++t)
    d = std::max({d, glm::length(a.triangles[t].v0 - b.triangles[t].v0),
                  glm::length(a.triangles[t].v1 - b.triangles[t].v1),
                  glm::length(a.triangles[t].v2 - b.triangles[t].v2)});
  return d;
}

// The animated, skinned and morphed models of ../shared/gltf-ext load with nothing
// ignored, and each animation moves them: at a third or two thirds of its length some
// corner has left its rest place.
TEST(Animation, ExtensionModelsPoseWithNothingIgnored) {
  VKPT_REQUIRE_SHARED_DATA();
  for (const char* file :
       {"AnimatedCube/glTF/AnimatedCube.gltf", "AnimatedTriangle/glTF/AnimatedTriangle.gltf", "Fox/glTF-Binary/Fox.glb",
        "InterpolationTest/glTF-Binary/InterpolationTest.glb",
        "MorphPrimitivesTest/glTF-Binary/MorphPrimitivesTest.glb", "RiggedSimple/glTF-Binary/RiggedSimple.glb",
        "SimpleMorph/glTF/SimpleMorph.gltf", "SimpleSkin/glTF/SimpleSkin.gltf",
        "AnimatedMorphCube/glTF-Quantized/AnimatedMorphCube.gltf"}) {
    SCOPED_TRACE(file);
    const std::string path = SharedData(std::string("gltf-ext/") + file);
    const Scene rest = LoadGltf(path);
    EXPECT_TRUE(rest.ignoredFeatures.empty()) << rest.ignoredFeatures.front();
    for (size_t a = 0; a < rest.animations.size(); ++a) {
      float moved = 0.0f;
      for (double share : {1.0 / 3, 2.0 / 3}) {
        const Scene posed =
            LoadGltf(path, {}, {.animation = std::to_string(a), .time = share * rest.animations[a].duration});
        ASSERT_EQ(posed.triangles.size(), rest.triangles.size());
        moved = std::max(moved, LargestMove(posed, rest));
      }
      std::printf("%s, animation %zu \"%s\" (%.4g s): a corner moved by %.4g\n", file, a,
                  rest.animations[a].name.c_str(), rest.animations[a].duration, moved);
      EXPECT_GT(moved, 1e-3f);
    }
  }
}

}  // namespace
}  // namespace vkpt::internal

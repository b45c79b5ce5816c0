// Vertex colours: glTF COLOR_0 through the loader (formats, transforms, validation) into
// the RenderScene's unorm16 TriangleColors, and in a render, where they multiply the base
// colour. (The GPU twin of the render test is in test_gpu.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "cpu/path_tracer.h"
#include "gltf_builder.h"
#include "render/render_scene.h"
#include "shared/vertex_color.h"

namespace vkpt::internal {
namespace {

using namespace test;

// Mesh `b.meshes.size()`: one primitive with POSITION and COLOR_0.
int MeshWithColors(GltfBuilder& b, int positions, int colors) {
  b.meshes.push_back(R"({"primitives":[{"attributes":{"POSITION":)" + std::to_string(positions) + R"(,"COLOR_0":)" +
                     std::to_string(colors) + "}}]}");
  return int(b.meshes.size()) - 1;
}

// The unit triangle with a COLOR_0 accessor of `type`, components `values` (as `T`).
template <class T>
GltfBuilder ColorModel(const std::vector<T>& values, int componentType, const std::string& type, bool normalized,
                       const std::string& nodeFields = "") {
  GltfBuilder b;
  const int n = type == "VEC4" ? 4 : 3;
  // Elements padded to 4-byte multiples, as glTF requires of vertex attributes.
  const int stride = int(((n * sizeof(T)) + 3) / 4 * 4);
  std::string bytes;
  for (size_t v = 0; v < values.size() / n; ++v) {
    std::string e = Bytes(std::vector<T>(values.begin() + v * n, values.begin() + (v + 1) * n));
    e.resize(stride, '\0');
    bytes += e;
  }
  const int colors = b.Accessor(b.View(bytes, stride == int(n * sizeof(T)) ? 0 : stride), componentType,
                                values.size() / n, type, normalized ? R"(,"normalized":true)" : "");
  MeshWithColors(b, b.Positions(kUnitTriangle), colors);
  b.Node(R"({"mesh":0)" + nodeFields + "}");
  return b;
}

::testing::AssertionResult SameColor(glm::vec4 a, glm::vec4 b) {
  if (a == b) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "(" << a.r << ", " << a.g << ", " << a.b << ", " << a.a << ") != (" << b.r
                                       << ", " << b.g << ", " << b.b << ", " << b.a << ")";
}

TEST(VertexColors, FloatVec3GetsOpaqueAlpha) {
  Scene s = Load(ColorModel<float>({1, 0, 0, 0, 0.5f, 0, 0, 0, 0.25f}, kFloat, "VEC3", false));
  ASSERT_EQ(s.colors.size(), 1u);
  EXPECT_TRUE(SameColor(s.colors[0].c0, {1, 0, 0, 1}));
  EXPECT_TRUE(SameColor(s.colors[0].c1, {0, 0.5f, 0, 1}));
  EXPECT_TRUE(SameColor(s.colors[0].c2, {0, 0, 0.25f, 1}));
  EXPECT_TRUE(s.warnings.empty()) << ::testing::PrintToString(s.warnings);
}

// Normalized integers map to k / (2^n − 1); packed as unorm16 for the renderers they come
// back bit for bit (8-bit ones too: 65535 = 255 · 257).
TEST(VertexColors, NormalizedIntegersSurviveThePackingExactly) {
  Scene s8 = Load(ColorModel<uint8_t>({255, 0, 1, 128, 7, 254, 3, 255, 0, 64, 200, 100}, kUByte, "VEC4", true));
  Scene s16 = Load(ColorModel<uint16_t>({65535, 0, 1, 32768, 7, 65534, 3, 65535, 0}, kUShort, "VEC3", true));
  ASSERT_EQ(s8.colors.size(), 1u);
  ASSERT_EQ(s16.colors.size(), 1u);
  EXPECT_TRUE(SameColor(s8.colors[0].c0, glm::vec4(255, 0, 1, 128) / 255.0f));
  EXPECT_TRUE(SameColor(s16.colors[0].c1, {32768.0f / 65535.0f, 7.0f / 65535.0f, 65534.0f / 65535.0f, 1.0f}));
  for (const Scene* s : {&s8, &s16}) {
    RenderScene rs = PrepareRenderScene(*s);
    ASSERT_EQ(rs.vertexColors.size(), 1u);
    const shader::TriangleColors& p = rs.vertexColors[0];
    const VertexColors& c = s->colors[0];
    EXPECT_TRUE(SameColor(shader::DecodeVertexColor(p.rg0, p.ba0), c.c0));
    EXPECT_TRUE(SameColor(shader::DecodeVertexColor(p.rg1, p.ba1), c.c1));
    EXPECT_TRUE(SameColor(shader::DecodeVertexColor(p.rg2, p.ba2), c.c2));
  }
}

TEST(VertexColors, MirroredNodeKeepsEachColorWithItsVertex) {
  Scene s = Load(ColorModel<float>({1, 0, 0, 0, 1, 0, 0, 0, 1}, kFloat, "VEC3", false, R"(,"scale":[-1,1,1])"));
  ASSERT_EQ(s.colors.size(), 1u);
  const SceneTriangle& t = s.triangles[0];
  EXPECT_TRUE(Near(t.v1, {0, 1, 0})) << "the winding fix swaps v1 and v2";
  EXPECT_TRUE(SameColor(s.colors[0].c1, {0, 0, 1, 1}));
  EXPECT_TRUE(SameColor(s.colors[0].c2, {0, 1, 0, 1}));
}

TEST(VertexColors, TrianglesWithoutThemAreWhite) {
  for (bool colorsFirst : {false, true}) {
    GltfBuilder b = TriangleModel();  // mesh 0: no colours
    MeshWithColors(b, b.Positions(kUnitTriangle),
                   b.Accessor(b.View(Bytes(std::vector<float>(9, 0.5f))), kFloat, 3, "VEC3"));
    b.Node(colorsFirst ? R"({"children":[2,1]})" : R"({"children":[1,2]})");
    b.Node(R"({"mesh":0})");
    b.Node(R"({"mesh":1})");
    Scene s = Load(b);
    ASSERT_EQ(s.colors.size(), 2u);
    const size_t plain = colorsFirst ? 1 : 0;
    EXPECT_TRUE(SameColor(s.colors[plain].c1, glm::vec4(1.0f)));
    EXPECT_TRUE(SameColor(s.colors[1 - plain].c1, {0.5f, 0.5f, 0.5f, 1.0f}));
  }
  GltfBuilder b = TriangleModel();
  b.Node(R"({"mesh":0})");
  Scene s = Load(b);
  EXPECT_TRUE(s.colors.empty());
  EXPECT_TRUE(PrepareRenderScene(s).vertexColors.empty());
}

TEST(VertexColors, FloatsOutsideTheUnitRangeAreClampedWithAWarning) {
  Scene s = Load(ColorModel<float>({2, -1, 0.5f, 0, 0, 0, 1, 1, 1}, kFloat, "VEC3", false));
  ASSERT_EQ(s.colors.size(), 1u);
  EXPECT_TRUE(SameColor(s.colors[0].c0, {1, 0, 0.5f, 1}));
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("COLOR_0: 2 component(s) outside [0, 1] clamped"), std::string::npos) << s.warnings[0];
}

TEST(VertexColors, InvalidAccessorsAreNamed) {
  const std::string where = "meshes[0].primitives[0].attributes.COLOR_0";
  const std::string rule = "must be a VEC3 or VEC4 accessor of FLOAT or normalized UNSIGNED_BYTE/UNSIGNED_SHORT";
  EXPECT_TRUE(FailsWith(ColorModel<float>({1, 1, 1, 1, 1, 1}, kFloat, "VEC2", false), {where, rule}));
  EXPECT_TRUE(FailsWith(ColorModel<uint8_t>({1, 1, 1, 1, 1, 1, 1, 1, 1}, kUByte, "VEC3", false), {where, rule}));
  EXPECT_TRUE(FailsWith(ColorModel<int16_t>({1, 1, 1, 1, 1, 1, 1, 1, 1}, kShort, "VEC3", true), {where, rule}));
  EXPECT_TRUE(FailsWith(ColorModel<float>({1, 1, 1, NAN, 1, 1, 1, 1, 1}, kFloat, "VEC3", false),
                        {where, "element 1", "not a finite colour"}));
  EXPECT_TRUE(FailsWith(ColorModel<float>({1, 1, 1, 1, 1, 1}, kFloat, "VEC3", false),
                        {where, "2 elements but POSITION has 3"}));
}

// Every sample of the quad is baseColor · COLOR_0(hit) · background: each pixel must lie
// within the colour's range over its footprint. Vertices paired with the wrong colours
// (b1 and b2 swapped in InterpolatedColor) put 4022 of 4096 pixels outside it (checked).
TEST(VertexColors, MultiplyTheBaseColorInARender) {
  const glm::vec3 base(0.8f, 0.6f, 1.0f);
  Scene s = VertexColorQuadScene(base);
  RenderScene rs = PrepareRenderScene(s);
  shader::FrameParams p = TestFrame(rs, s, 64, 4, 3, 4);
  p.background = glm::vec3(2.0f, 1.0f, 0.5f);
  RenderResult r = RenderCpu(rs, p);
  const int off = PixelsOffVertexColorQuad(r.image, p, base);
  std::printf("vertex-coloured quad: %d of %zu pixels outside their footprint's colour range (must be 0)\n", off,
              r.image.pixels.size());
  EXPECT_EQ(off, 0);
}

}  // namespace
}  // namespace vkpt::internal

// Normal maps (shared/normal_map.h) in a render: a Lambert square facing the camera
// under a directional light, its normal map one texel, so that every pixel's radiance is
// ρ/π · E · cos θ with θ between the light and the mapped normal: the tangent frame
// (tangent, bitangent sign), the scale and a flat map are checked against that closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "cpu/path_tracer.h"
#include "gpu_test.h"
#include "render/render_scene.h"
#include "test_util.h"
#include "vk/vk_renderer.h"

namespace vkpt::internal {
namespace {

using namespace test;

constexpr float kAlbedo = 0.8f;

// The square [−1, 1]² at z = 0 facing +z, Lambertian, lit by a directional light of
// irradiance 1 arriving from `toLight`; with `texel` (RGB bytes), a normal map of that
// one texel, tangent `tangent` (xyz, w) at every vertex and scale `scale`.
Scene LitSquare(glm::vec3 toLight, const glm::u8vec3* texel, glm::vec4 tangent, float scale = 1.0f) {
  Material m{};
  m.baseColor = glm::vec3(kAlbedo);
  m.roughness = 1.0f;
  const glm::vec3 a(-1, -1, 0), b(1, -1, 0), c(1, 1, 0), d(-1, 1, 0);
  Scene s = MakeScene({{a, b, c, 0}, {a, c, d, 0}}, {m});
  s.cameras.push_back(OrthographicAlongMinusZ(2.0f, 0.9f));
  PunctualLight light;
  light.type = PunctualLight::Type::kDirectional;
  light.direction = -glm::normalize(toLight);
  light.intensity = glm::vec3(1.0f);
  s.lights.push_back(light);
  if (texel) {
    s.materials[0].normalScale = scale;
    s.images.push_back({"normal", 1, 1, {texel->r, texel->g, texel->b, 255}});
    s.textures.push_back(test::TextureWithMode(0, 0u));
    s.materials[0].texture(TextureSlot::kNormal).texture = 0;
    s.uvs.assign(2, VertexUVs{});
    s.tangents.assign(2, VertexTangents{{tangent, tangent, tangent}});
  }
  return s;
}

shader::FrameParams Frame(const RenderScene& rs, const Scene& s) {
  shader::FrameParams p = TestFrame(rs, s, 16, 1, 1, 1);
  p.rrDepth = 100;  // no roulette: each sample is the closed form exactly
  p.background = glm::vec3(0.0f);
  return p;
}

Image Render(const Scene& s) {
  RenderScene rs = PrepareRenderScene(s);
  return RenderCpu(rs, Frame(rs, s)).image;
}

// The normal a texel encodes, with x and y scaled, as the spec's scaledNormal.
glm::dvec3 TexelNormal(glm::u8vec3 t, double scale) {
  glm::dvec3 n = glm::dvec3(t) / 255.0 * 2.0 - 1.0;
  return glm::normalize(glm::dvec3(n.x * scale, n.y * scale, n.z));
}

// The largest relative difference of any pixel from `expected` (all channels alike).
double WorstRelativeError(const Image& image, double expected) {
  double worst = 0.0;
  for (const glm::vec3& px : image.pixels) worst = std::max(worst, std::abs(px.r - expected) / expected);
  return worst;
}

// In the tangent frame (T, B, N) = (x, w·y, z) of the square, a texel tilted towards
// ±x or ±y by 30°, lit from 40° off the normal on the +x or +y side.
struct Case {
  const char* name;
  glm::u8vec3 texel;
  glm::vec4 tangent;
  glm::vec3 toLight;
  glm::dvec3 worldNormal;  // the texel's normal in world space, for this tangent frame
};

TEST(NormalMaps, TangentFrameMatchesTheClosedForm) {
  const double s30 = 0.5, c30 = std::sqrt(3.0) / 2.0;
  const auto byte = [](double v) { return uint8_t(std::lround((v + 1.0) / 2.0 * 255.0)); };
  const glm::u8vec3 towardsT(byte(s30), 128, byte(c30)), towardsB(128, byte(s30), byte(c30));
  const glm::vec3 fromX(std::sin(0.7f), 0.0f, std::cos(0.7f)), fromY(0.0f, std::sin(0.7f), std::cos(0.7f));
  auto world = [&](glm::u8vec3 t, glm::dvec3 tangent, glm::dvec3 bitangent) {
    glm::dvec3 n = TexelNormal(t, 1.0);
    return n.x * tangent + n.y * bitangent + n.z * glm::dvec3(0, 0, 1);
  };
  const Case cases[] = {
      {"tilt towards T = +x, lit from +x", towardsT, {1, 0, 0, 1}, fromX, world(towardsT, {1, 0, 0}, {0, 1, 0})},
      {"tilt towards T = −x, lit from +x", towardsT, {-1, 0, 0, 1}, fromX, world(towardsT, {-1, 0, 0}, {0, -1, 0})},
      {"tilt towards B = +y (w = 1)", towardsB, {1, 0, 0, 1}, fromY, world(towardsB, {1, 0, 0}, {0, 1, 0})},
      {"tilt towards B = −y (w = −1)", towardsB, {1, 0, 0, -1}, fromY, world(towardsB, {1, 0, 0}, {0, -1, 0})},
  };
  for (const Case& c : cases) {
    const double expected = kAlbedo / M_PI * glm::dot(c.worldNormal, glm::normalize(glm::dvec3(c.toLight)));
    const double worst = WorstRelativeError(Render(LitSquare(c.toLight, &c.texel, c.tangent)), expected);
    std::printf("%s: expected %.6f, worst relative error %.2e\n", c.name, expected, worst);
    EXPECT_LT(worst, 1e-4) << c.name;
  }
}

// normalTexture.scale scales x and y of the tangent-space normal before normalizing.
TEST(NormalMaps, ScaleBendsTheNormalFurther) {
  const glm::u8vec3 texel(191, 128, 238);
  const glm::vec3 toLight(std::sin(0.7f), 0.0f, std::cos(0.7f));
  for (float scale : {0.0f, 0.5f, 1.5f}) {
    const glm::dvec3 n = TexelNormal(texel, scale);
    const double expected = kAlbedo / M_PI * glm::dot(glm::dvec3(n.x, n.y, n.z), glm::normalize(glm::dvec3(toLight)));
    const double worst = WorstRelativeError(Render(LitSquare(toLight, &texel, {1, 0, 0, 1}, scale)), expected);
    std::printf("scale %.1f: expected %.6f, worst relative error %.2e\n", scale, expected, worst);
    EXPECT_LT(worst, 1e-4) << "scale " << scale;
  }
}

// A flat map, (128, 128, 255) = a normal 0.3° off (0, 0, 1) (8 bits cannot say 0.5),
// renders what no map does, within the cosine of that tilt.
TEST(NormalMaps, FlatMapChangesNothing) {
  const glm::u8vec3 flat(128, 128, 255);
  const glm::vec3 toLight(0.3f, -0.2f, 1.0f);
  const Image plain = Render(LitSquare(toLight, nullptr, {}));
  const Image mapped = Render(LitSquare(toLight, &flat, {1, 0, 0, 1}));
  double worst = 0.0;
  for (size_t i = 0; i < plain.pixels.size(); ++i)
    worst = std::max(worst, double(std::abs(plain.pixels[i].r - mapped.pixels[i].r) / plain.pixels[i].r));
  std::printf("flat normal map vs none: worst relative difference %.2e\n", worst);
  EXPECT_LT(worst, 1e-3);
  EXPECT_GT(plain.pixels[0].r, 0.0f);
}

// Without tangents (a primitive without texture coordinates to derive them from) the
// map is not applied, rather than bent around an arbitrary direction.
TEST(NormalMaps, MissingTangentsLeaveTheNormal) {
  const glm::u8vec3 tilted(191, 128, 238);
  const glm::vec3 toLight(std::sin(0.7f), 0.0f, std::cos(0.7f));
  const double expected = kAlbedo / M_PI * std::cos(0.7);
  const double worst = WorstRelativeError(Render(LitSquare(toLight, &tilted, {0, 0, 0, 1})), expected);
  std::printf("no tangents: expected %.6f, worst relative error %.2e\n", expected, worst);
  EXPECT_LT(worst, 1e-4);
}

class NormalMapsGpu : public ValidatedGpuTest {};

// The GPU bends the normal as the CPU does: the bitangent-sign case, pixel for pixel.
TEST_F(NormalMapsGpu, MatchTheCpu) {
  const glm::u8vec3 texel(128, 64, 238);
  const Scene s = LitSquare({0.0f, std::sin(0.7f), std::cos(0.7f)}, &texel, {0.6f, 0.8f, 0, -1});
  RenderScene rs = PrepareRenderScene(s);
  vk::GpuRenderer gpu(Gpu(), rs);
  const Image g = gpu.Render(Frame(rs, s)).image, c = RenderCpu(rs, Frame(rs, s)).image;
  double worst = 0.0;
  for (size_t i = 0; i < c.pixels.size(); ++i)
    worst = std::max(worst, double(std::abs(g.pixels[i].r - c.pixels[i].r) / c.pixels[i].r));
  std::printf("normal-mapped square, GPU vs CPU: worst relative difference %.2e (radiance %.6f)\n", worst,
              c.pixels[0].r);
  EXPECT_LT(worst, 1e-5);
}

}  // namespace
}  // namespace vkpt::internal

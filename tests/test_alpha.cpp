// Alpha coverage (shared/alpha.h) in renders with closed-form answers: a black occluder
// between a directional light shining straight down and a Lambert floor, seen from
// above by an orthographic camera. A floor point is lit only if both its camera ray and
// its shadow ray get through the occluder, so a pixel is ρ/π · E times that:
//   MASK:  the camera ray and the shadow ray cross the occluder at the same point, so a
//          pixel is ρ/π where the mask is open and 0 where it is closed, exactly;
//   BLEND: each ray decides on its own, so the image mean is (1 − α)² ρ/π (z-test).
// And an emitter with BLEND alpha α lights the floor as an opaque one emitting α·Le, both
// strategies of MIS included.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "cpu/path_tracer.h"
#include "gpu_test.h"
#include "image/image_compare.h"
#include "render/render_scene.h"
#include "test_util.h"
#include "vk/vk_renderer.h"

namespace vkpt::internal {
namespace {

using namespace test;

constexpr float kAlbedo = 0.8f;
const double kLitFloor = kAlbedo / M_PI;  // ρ/π · E · cos 0, E = 1

// Two triangles facing +z over [x0, x1] × [y0, y1] at height z, of material m.
void AddSquare(std::vector<SceneTriangle>& tris, float x0, float x1, float y0, float y1, float z, uint32_t m) {
  const glm::vec3 a(x0, y0, z), b(x1, y0, z), c(x1, y1, z), d(x0, y1, z);
  tris.push_back({a, b, c, m});
  tris.push_back({a, c, d, m});
}

Material Lambert(float albedo) {
  Material m{};
  m.baseColor = glm::vec3(albedo);
  m.roughness = 1.0f;
  m.alpha = 1.0f;
  return m;
}

// The floor [−1, 1]² at z = 0 (material 0) under the occluder [−1, 1]² at z = 0.5
// (material 1, black, with its alpha), lit straight down with E = 1, seen along −z over
// [−0.9, 0.9]². Texture coordinates run over the occluder like an image: u from left to
// right, v from top to bottom.
Scene OccluderScene(const Material& occluder) {
  std::vector<SceneTriangle> tris;
  AddSquare(tris, -1, 1, -1, 1, 0.0f, 0);
  AddSquare(tris, -1, 1, -1, 1, 0.5f, 1);
  Scene s = MakeScene(tris, {Lambert(kAlbedo), occluder});
  s.cameras.push_back(OrthographicAlongMinusZ(2.0f, 0.9f));
  PunctualLight light;
  light.type = PunctualLight::Type::kDirectional;
  light.direction = glm::vec3(0, 0, -1);
  light.intensity = glm::vec3(1.0f);
  s.lights.push_back(light);
  return s;
}

// The occluder cut by a 2 × 2 NEAREST alpha texture: bytes 127 at the top left and
// bottom right, 128 elsewhere. With alphaCutoff 0.5, 127/255 is cut and 128/255 kept.
Scene MaskedOccluderScene() {
  Material m = Lambert(0.0f);
  m.alphaMode = AlphaMode::kMask;
  m.alphaCutoff = 0.5f;
  Scene s = OccluderScene(m);
  auto uv = [](glm::vec3 p) { return glm::vec2(0.5f * (p.x + 1.0f), 0.5f * (1.0f - p.y)); };
  for (const SceneTriangle& t : s.triangles) s.uvs.push_back({{uv(t.v0), uv(t.v1), uv(t.v2)}, {}});
  s.images.push_back({"mask", 2, 2, {0, 0, 0, 127, 0, 0, 0, 128, 0, 0, 0, 128, 0, 0, 0, 127}});
  s.textures.push_back(TextureWithMode(0, 0u, true));
  s.materials[1].texture(TextureSlot::kBaseColor).texture = 0;
  return s;
}

// The occluder BLEND with α = 0.3: baseColorFactor's 0.6 times COLOR_0's 0.5.
Scene BlendedOccluderScene() {
  Material m = Lambert(0.0f);
  m.alphaMode = AlphaMode::kBlend;
  m.alpha = 0.6f;
  Scene s = OccluderScene(m);
  const glm::vec4 half(1.0f, 1.0f, 1.0f, 0.5f);
  for (const SceneTriangle& t : s.triangles)
    s.colors.push_back(t.material == 1 ? VertexColors{half, half, half} : VertexColors{});
  return s;
}
constexpr double kBlendAlpha = 0.6 * 0.5;

shader::FrameParams Frame(const RenderScene& rs, const Scene& s, uint32_t size, uint32_t spp) {
  shader::FrameParams p = TestFrame(rs, s, size, spp, 7, 2);
  p.background = glm::vec3(0.0f);
  return p;
}

// Pixels of a 16 × 16 render of MaskedOccluderScene off their exact value: ρ/π in the
// open quadrants (top left, bottom right), 0 in the others.
int PixelsOffMask(const Image& img) {
  int off = 0;
  for (uint32_t y = 0; y < img.height; ++y)
    for (uint32_t x = 0; x < img.width; ++x) {
      const bool open = (x < img.width / 2) == (y < img.height / 2);
      const glm::vec3 v = img.pixels[y * img.width + x];
      const double expected = open ? kLitFloor : 0.0;
      for (int c = 0; c < 3; ++c) off += std::abs(v[c] - expected) > 1e-6 * kLitFloor;
    }
  return off;
}

TEST(Alpha, MaskPassesCameraAndShadowRaysWhereTheTextureIsBelowTheCutoff) {
  Scene s = MaskedOccluderScene();
  RenderScene rs = PrepareRenderScene(s);
  ASSERT_TRUE(rs.alphaTested);
  const Image img = RenderCpu(rs, Frame(rs, s, 16, 4)).image;
  const int off = PixelsOffMask(img);
  std::printf("masked occluder: %d of %zu channels off ρ/π (open) or 0 (closed)\n", off, 3 * img.pixels.size());
  EXPECT_EQ(off, 0);
  const ZTest t = MeanAndError(img, glm::dvec3(0.5 * kLitFloor));
  EXPECT_NEAR(t.mean.x, 0.5 * kLitFloor, 1e-6) << "half the area, half the light";
}

TEST(Alpha, BlendTransmitsOneMinusAlphaPerRay) {
  Scene s = BlendedOccluderScene();
  RenderScene rs = PrepareRenderScene(s);
  const Image img = RenderCpu(rs, Frame(rs, s, 32, 256)).image;
  // A floor pixel needs the camera ray and the shadow ray through: (1 − α)², not 1 − α.
  const glm::dvec3 expected((1.0 - kBlendAlpha) * (1.0 - kBlendAlpha) * kLitFloor);
  EXPECT_TRUE(Agrees(MeanAndError(img, expected), expected, 0.0, "BLEND occluder (1 - a)^2 rho/pi"));
}

// A BLEND emitter of radiance 1 and α = 0.4 lights the floor as an opaque one of 0.4 does:
// light samples weigh its emission by the coverage, BSDF-sampled rays find it with
// probability α. The emitter, [1.2, 2.2] × [−0.5, 0.5] at z = 0.5 facing down, is out of
// the camera's view.
Scene EmitterScene(bool blended) {
  Material emitter = Lambert(0.0f);
  emitter.emission = glm::vec3(blended ? 1.0f : 0.4f);
  if (blended) {
    emitter.alphaMode = AlphaMode::kBlend;
    emitter.alpha = 0.4f;
  }
  std::vector<SceneTriangle> tris;
  AddSquare(tris, -2.5f, 2.5f, -2.5f, 2.5f, 0.0f, 0);
  const glm::vec3 a(1.2f, -0.5f, 0.5f), b(2.2f, -0.5f, 0.5f), c(2.2f, 0.5f, 0.5f), d(1.2f, 0.5f, 0.5f);
  tris.push_back({a, c, b, 1});  // clockwise seen from above: the front faces down
  tris.push_back({a, d, c, 1});
  Scene s = MakeScene(tris, {Lambert(kAlbedo), emitter});
  s.cameras.push_back(OrthographicAlongMinusZ(2.0f, 0.9f));
  return s;
}

TEST(Alpha, BlendedEmitterLightsLikeAnOpaqueOneOfAlphaTimesItsRadiance) {
  ZTest t[2];
  for (int blended = 0; blended < 2; ++blended) {
    Scene s = EmitterScene(blended);
    RenderScene rs = PrepareRenderScene(s);
    EXPECT_EQ(rs.alphaTested, blended == 1);
    shader::FrameParams p = Frame(rs, s, 32, 256);
    p.maxDepth = 1;  // direct light only
    t[blended] = MeanAndError(RenderCpu(rs, p).image, glm::dvec3(0.0));
  }
  for (int c = 0; c < 3; ++c) {
    const double z = (t[1].mean[c] - t[0].mean[c]) / std::hypot(t[0].stderr_[c], t[1].stderr_[c]);
    std::printf("channel %d: opaque 0.4 %.6f ± %.1e, BLEND 0.4 of 1 %.6f ± %.1e, z %.2f (|z| < 3.2)\n", c, t[0].mean[c],
                t[0].stderr_[c], t[1].mean[c], t[1].stderr_[c], z);
    EXPECT_GT(t[0].mean[c], 0.0);
    EXPECT_LT(std::abs(z), 3.2);
  }
}

// The GPU's stackless walk meets triangles in another order than the CPU's, yet every
// alpha decision is the same: the images agree in lockstep.
class AlphaGpu : public ValidatedGpuTest {};

TEST_F(AlphaGpu, MaskAndBlendRenderAsOnTheCpu) {
  for (const Scene& s : {MaskedOccluderScene(), BlendedOccluderScene()}) {
    RenderScene rs = PrepareRenderScene(s);
    const shader::FrameParams p = Frame(rs, s, 16, 16);
    vk::GpuRenderer gpu(Gpu(), rs);
    const Image g = gpu.Render(p).image;
    const Image c = RenderCpu(rs, p).image;
    // One decision made differently changes a pixel by ρ/π over its 16 samples; rounding
    // in the shading changes it by 1e-7.
    int differing = 0;
    for (size_t i = 0; i < g.pixels.size(); ++i)
      differing += glm::any(glm::greaterThan(glm::abs(g.pixels[i] - c.pixels[i]), glm::vec3(1e-5 * kLitFloor)));
    const ImageComparison cmp = CompareImages(c, g);
    std::printf("%s occluder: %d of %zu pixels differ beyond rounding; %s\n",
                s.materials[1].alphaMode == AlphaMode::kMask ? "MASK" : "BLEND", differing, g.pixels.size(),
                cmp.Summary().c_str());
    EXPECT_EQ(differing, 0);
    EXPECT_TRUE(cmp.lockstepAgree);
    if (s.materials[1].alphaMode == AlphaMode::kMask) {
      EXPECT_EQ(PixelsOffMask(g), 0);
    }
  }
}

}  // namespace
}  // namespace vkpt::internal

// Ray cones (shared/ray_cone.h): the camera's cone, the level a footprint picks, the
// curvature of vertex normals; which lookups a cone filters (path.h's TextureCones): an
// unlit quad 16 pixels wide whose texture is 64 texels wide reads level 2, the level whose
// texels are its pixels, where a later vertex's colour lookup would, and level 0 where
// the camera sees it (both backends render it as --texture-lod none does, bit for bit).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "cpu/cpu_path.h"
#include "cpu/path_tracer.h"
#include "gpu_test.h"
#include "render/render_scene.h"
#include "render/scene_access.h"
#include "shared/ray_cone.h"
#include "shared/texture.h"
#include "test_util.h"
#include "vk/vk_renderer.h"

namespace vkpt::internal {
namespace {

using namespace test;

TEST(RayCones, CameraConeSpansOnePixel) {
  shader::FrameParams p{};
  p.height = 100;
  p.tanHalfFovY = std::tan(0.5f);
  const glm::vec2 perspective = shader::CameraCone(p);  // (spread, width)
  EXPECT_FLOAT_EQ(perspective.x, 2.0f * std::tan(0.5f) / 100.0f);
  EXPECT_EQ(perspective.y, 0.0f);
  p.orthographic = 1;
  p.tanHalfFovY = 2.0f;  // half the view's height
  const glm::vec2 orthographic = shader::CameraCone(p);
  EXPECT_EQ(orthographic.x, 0.0f);
  EXPECT_FLOAT_EQ(orthographic.y, 0.04f);
  EXPECT_FLOAT_EQ(shader::ConeWidthAt(0.0f, 0.01f, 3.0f), 0.03f);
  EXPECT_FLOAT_EQ(shader::ConeWidthAt(0.05f, -0.01f, 10.0f), 0.05f);  // converged and opened again
}

TEST(RayCones, FootprintGrowsWithWidthAndObliquity) {
  const glm::vec3 e1(2, 0, 0), e2(2, 2, 0);  // twice the area: 4
  // log2(width) − log2(cos) − ½ log2(twice the area)
  EXPECT_EQ(shader::FootprintLod(0.125f, 1.0f, e1, e2), -3.0f - 1.0f);
  EXPECT_EQ(shader::FootprintLod(0.25f, 1.0f, e1, e2), -2.0f - 1.0f);
  EXPECT_EQ(shader::FootprintLod(0.125f, -0.5f, e1, e2), -3.0f + 1.0f - 1.0f);
  EXPECT_EQ(shader::FootprintLod(0.0f, 1.0f, e1, e2), shader::kLevelZero);
  // A 64 × 64 texture over the triangle's UV area ½ (twice: 1): + ½ log2(64²) = 6.
  shader::TriangleUVs uvs{{0, 0}, {1, 0}, {1, 1}, {0, 0}, {0, 0}, {0, 0}};
  shader::TextureRef ref{0, 0, 1, 0, 0, 0, 1, 0};
  shader::Texture tex{0, 64, 64, 0};
  EXPECT_EQ(shader::TextureLod(-4.0f, ref, tex, uvs), 2.0f);
  ref.m00 = ref.m11 = 0.5f;  // KHR_texture_transform scale ½: a quarter of the texels
  EXPECT_EQ(shader::TextureLod(-4.0f, ref, tex, uvs), 1.0f);
}

TEST(RayCones, CurvatureOfASphereIsOneOverItsRadius) {
  const float r = 2.0f;
  const glm::vec3 p0 = r * glm::normalize(glm::vec3(1, 0.1f, 0.2f));
  const glm::vec3 p1 = r * glm::normalize(glm::vec3(0.9f, 0.4f, 0.1f));
  const glm::vec3 p2 = r * glm::normalize(glm::vec3(0.8f, 0.2f, 0.5f));
  const glm::vec3 e1 = p1 - p0, e2 = p2 - p0;
  EXPECT_NEAR(shader::TriangleCurvature(p0 / r, p1 / r, p2 / r, e1, e2), 1.0f / r, 1e-5f);      // convex
  EXPECT_NEAR(shader::TriangleCurvature(-p0 / r, -p1 / r, -p2 / r, e1, e2), -1.0f / r, 1e-5f);  // concave
  const glm::vec3 n(0, 0, 1);
  EXPECT_EQ(shader::TriangleCurvature(n, n, n, e1, e2), 0.0f);  // flat
  // A saddle: the normal turns towards one edge and away from another.
  const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_EQ(shader::TriangleCurvature(n, glm::normalize(glm::vec3(0.3f, 0, 1)), glm::normalize(glm::vec3(0, -0.3f, 1)),
                                      b - a, c - a),
            0.0f);
  // Scattering adds twice the curvature over the width, and the BSDF's spread.
  EXPECT_FLOAT_EQ(shader::ScatteredSpread(0.01f, 0.1f, 0.5f, 1e6f), 0.01f + 0.1f + 0.25f / (shader::kPi * 1e6f));
  EXPECT_FLOAT_EQ(shader::ScatteredSpread(0.0f, 0.0f, 0.0f, 0.5f / shader::kPi), shader::kDiffuseSpread);
}

// The unlit quad [−1, 1]² framed exactly by an orthographic camera, with a 64 × 64 texture
// of random bytes, NEAREST within a level and between levels (NEAREST_MIPMAP_NEAREST).
Scene MipQuadScene() {
  Scene s = TexturedQuadScene();
  TextureImage& im = s.images[0];
  im.width = im.height = 64;
  im.rgba.resize(64 * 64 * 4);
  std::mt19937 rng(5);
  for (uint8_t& b : im.rgba) b = uint8_t(rng());
  s.textures[0] = test::TextureWithMode(0, shader::kTextureMipNearest, true);
  return s;
}

// Pixels of a 16 × 16 render of MipQuadScene other than the level-2 texel under them:
// each pixel covers one texel of level 2 (16 × 16), whatever its samples' jitter.
int PixelsOffLevelTwo(const RenderScene& rs, const Image& img) {
  int off = 0;
  for (uint32_t y = 0; y < 16; ++y)
    for (uint32_t x = 0; x < 16; ++x) {
      const glm::vec2 uv((x + 0.5f) / 16.0f, (y + 0.5f) / 16.0f);
      const glm::vec4 texel =
          shader::SampleTexture(rs, rs.textures[0], uv, 2.0f, shader::SlotIsSrgb(shader::kSlotBaseColor));
      off += img.pixels[y * 16 + x] != glm::vec3(texel);
    }
  return off;
}

// What the camera sees is read at level 0 with ray cones too: the render equals the one
// of --texture-lod none, whose pixels average the 4 × 4 random texels under them.
TEST(RayCones, CameraHitsReadLevelZero) {
  Scene s = MipQuadScene();
  RenderScene rs = PrepareRenderScene(s);
  shader::FrameParams p = TestFrame(rs, s, 16, 2, 3, 1);
  p.background = glm::vec3(0.0f);
  ASSERT_EQ(p.textureLod, 1u);
  const Image cones = RenderCpu(rs, p).image;
  p.textureLod = 0;
  const Image none = RenderCpu(rs, p).image;
  const int off = PixelsOffLevelTwo(rs, cones);
  std::printf("camera hits with ray cones: %d of 256 pixels off their level-2 texel (level 0 read)\n", off);
  EXPECT_TRUE(cones.pixels == none.pixels);
  EXPECT_GT(off, 200);
}

// A later vertex reads its colour textures at its cone's level and its data textures and
// normal maps at level 0: MakeSurfaceHit on the quad with the cone of a pixel (2/16 wide)
// for colour gives the level-2 texel, and that cone for data leaves the colour at level 0.
TEST(RayCones, LaterVerticesFilterColourOnly) {
  shader::FrameParams p{};
  p.textureLod = 1u;
  EXPECT_EQ(shader::TextureCones(p, 0u, 0.5f), glm::vec2(0.0f));
  EXPECT_EQ(shader::TextureCones(p, 1u, 0.5f), glm::vec2(0.5f, 0.0f));
  EXPECT_EQ(shader::TextureCones(p, 3u, 0.25f), glm::vec2(0.25f, 0.0f));
  p.textureLod = 0u;
  EXPECT_EQ(shader::TextureCones(p, 2u, 0.5f), glm::vec2(0.0f));
  const RenderScene rs = PrepareRenderScene(MipQuadScene());
  int offColour = 0, offData = 0;
  for (uint32_t y = 0; y < 16; ++y)
    for (uint32_t x = 0; x < 16; ++x) {
      const glm::vec2 uv((x + 0.5f) / 16.0f, (y + 0.5f) / 16.0f);
      // The quad spans [−1, 1]² with v down the image; straight on from −z.
      const shader::Ray ray{glm::vec3(2.0f * uv.x - 1.0f, 1.0f - 2.0f * uv.y, -5.0f), glm::vec3(0, 0, 1)};
      const Hit hit = IntersectClosest(rs, ray.origin, ray.dir, shader::kInfinity);
      ASSERT_GE(hit.t, 0.0f);
      const glm::vec3 level2(
          shader::SampleTexture(rs, rs.textures[0], uv, 2.0f, shader::SlotIsSrgb(shader::kSlotBaseColor)));
      const glm::vec3 level0(
          shader::SampleTexture(rs, rs.textures[0], uv, 0.0f, shader::SlotIsSrgb(shader::kSlotBaseColor)));
      offColour += shader::MakeSurfaceHit(rs, ray, hit, glm::vec2(0.125f, 0.0f)).material.baseColor != level2;
      offData += shader::MakeSurfaceHit(rs, ray, hit, glm::vec2(0.0f, 0.125f)).material.baseColor != level0;
    }
  EXPECT_EQ(offColour, 0) << "colour lookups at the cone's level";
  EXPECT_EQ(offData, 0) << "a data cone must not filter the colour";
}

class RayConesGpu : public ValidatedGpuTest {};

TEST_F(RayConesGpu, CameraHitsReadLevelZero) {
  Scene s = MipQuadScene();
  RenderScene rs = PrepareRenderScene(s);
  shader::FrameParams p = TestFrame(rs, s, 16, 2, 3, 1);
  p.background = glm::vec3(0.0f);
  vk::GpuRenderer gpu(Gpu(), rs);
  const Image cones = gpu.Render(p).image;
  p.textureLod = 0;
  const Image none = gpu.Render(p).image;
  const int off = PixelsOffLevelTwo(rs, cones);
  std::printf("GPU camera hits with ray cones: %d of 256 pixels off their level-2 texel\n", off);
  EXPECT_TRUE(cones.pixels == none.pixels);
  EXPECT_GT(off, 200);
}

}  // namespace
}  // namespace vkpt::internal

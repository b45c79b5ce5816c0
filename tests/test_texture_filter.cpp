// Texture filtering (shared/texture.h) on the CPU: wrap modes, nearest and bilinear
// magnification, mip selection and trilinear minification against hand-computed texel
// values, the exact byte → float tables, and mip chains that keep the image's mean.
// (The GPU returns the same bits: test_texture_gpu.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "cpu/cpu_path.h"
#include "render/render_scene.h"
#include "render/texture_store.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

constexpr uint32_t kLinearFilters = shader::kTextureMagLinear | shader::kTextureMinLinear;

// A RenderScene holding one texture and nothing else (the filtering code reads nothing
// else): `bytes` are RGBA8 texels, row-major from the top.
RenderScene OneTexture(uint32_t w, uint32_t h, const std::vector<uint8_t>& bytes, uint32_t mode) {
  Scene s;
  s.images.push_back({"test", w, h, bytes});
  s.textures.push_back(test::TextureWithMode(0, mode));
  return test::TexturesOnly(s);
}

// A w × h texture whose texel (x, y) has R = x·step, G = y·step, B = 0, A = 255.
RenderScene Ramp(uint32_t w, uint32_t h, uint8_t step, uint32_t mode) {
  std::vector<uint8_t> bytes;
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) bytes.insert(bytes.end(), {uint8_t(x * step), uint8_t(y * step), 0, 255});
  return OneTexture(w, h, bytes, mode);
}

// The first texture at `uv` and level of detail `lod`, its RGB read as colour (`srgb`) or data.
glm::vec4 Lookup(const RenderScene& scene, glm::vec2 uv, float lod = 0.0f, bool srgb = false) {
  return shader::SampleTexture(scene, scene.textures[0], uv, lod, srgb);
}

float Byte(int b) { return float(double(b) / 255.0); }

uint32_t Wrap(uint32_t s, uint32_t t) { return s << shader::kTextureWrapSShift | t << shader::kTextureWrapTShift; }

TEST(TextureFilter, ByteTablesAreExactlyRounded) {
  const std::vector<float> table = TexelDecodeTable();
  ASSERT_EQ(table.size(), shader::kTexelDecodeSize);
  for (int b = 0; b < 256; ++b) {
    // IEC 61966-2-1 in long double, rounded once to float.
    const long double e = b / 255.0L;
    const long double l = e <= 0.04045L ? e / 12.92L : std::pow((e + 0.055L) / 1.055L, 2.4L);
    EXPECT_EQ(table[b], float(l)) << "sRGB byte " << b;
    EXPECT_EQ(table[shader::kTexelDecodeLinear + b], float(e)) << "linear byte " << b;
    EXPECT_EQ(shader::UnormByte(uint32_t(b)), float(e)) << "linear byte " << b << ", computed";
  }
  EXPECT_EQ(table[0], 0.0f);
  EXPECT_EQ(table[255], 1.0f);
  EXPECT_NEAR(table[128], 0.2158605f, 1e-7f);  // the textbook value of sRGB 128
}

TEST(TextureFilter, NearestPicksTheTexelUnderThePointInEveryWrapMode) {
  using namespace shader;
  const uint32_t modes[3] = {kWrapRepeat, kWrapClampToEdge, kWrapMirroredRepeat};
  // u → the texel column of a 4-wide texture, for repeat, clamp, mirrored repeat.
  const struct {
    float u;
    int column[3];
  } cases[] = {{0.1f, {0, 0, 0}},  {0.9f, {3, 3, 3}}, {-0.1f, {3, 0, 0}}, {1.1f, {0, 3, 3}},
               {-0.6f, {1, 0, 2}}, {2.3f, {1, 3, 1}}, {-1.3f, {2, 0, 2}}, {0.0f, {0, 0, 0}}};
  for (int m = 0; m < 3; ++m) {
    RenderScene tex = Ramp(4, 2, 10, Wrap(modes[m], kWrapClampToEdge));
    for (const auto& c : cases) {
      glm::vec4 v = Lookup(tex, {c.u, 0.75f});
      EXPECT_EQ(v.r, Byte(10 * c.column[m])) << "mode " << m << " u " << c.u;
      EXPECT_EQ(v.g, Byte(10)) << "mode " << m << " u " << c.u;  // row 1
      EXPECT_EQ(v.a, 1.0f);
    }
  }
}

TEST(TextureFilter, BilinearBlendsTheFourTexelsAroundThePoint) {
  using namespace shader;
  RenderScene tex = Ramp(4, 4, 80, Wrap(kWrapClampToEdge, kWrapClampToEdge) | kLinearFilters);
  // At a texel's centre: that texel alone.
  EXPECT_EQ(Lookup(tex, {1.5f / 4, 2.5f / 4}), glm::vec4(Byte(80), Byte(160), 0, 1));
  // Halfway between two columns' centres and a quarter of the way between two rows'.
  glm::vec4 v = Lookup(tex, {2.0f / 4, 1.75f / 4});
  EXPECT_FLOAT_EQ(v.r, 0.5f * (Byte(80) + Byte(160)));
  EXPECT_FLOAT_EQ(v.g, 0.75f * Byte(80) + 0.25f * Byte(160));
  // Half a texel inside the left edge: clamp reads the edge column alone; repeat blends it
  // with the last column; mirrored repeat with the edge column itself.
  EXPECT_EQ(Lookup(tex, {0.0f, 0.5f / 4}).r, 0.0f);
  RenderScene repeat = Ramp(4, 4, 80, Wrap(kWrapRepeat, kWrapClampToEdge) | kLinearFilters);
  EXPECT_FLOAT_EQ(Lookup(repeat, {0.0f, 0.5f / 4}).r, 0.5f * Byte(240));
  RenderScene mirror = Ramp(4, 4, 80, Wrap(kWrapMirroredRepeat, kWrapClampToEdge) | kLinearFilters);
  EXPECT_EQ(Lookup(mirror, {0.0f, 0.5f / 4}).r, 0.0f);
  EXPECT_EQ(Lookup(mirror, {-0.5f / 4, 0.5f / 4}).r, 0.0f);
}

TEST(TextureFilter, SrgbTexturesAreDecodedBeforeFiltering) {
  using namespace shader;
  const std::vector<float> table = TexelDecodeTable();
  RenderScene tex =
      OneTexture(2, 1, {0, 0, 0, 0, 255, 255, 255, 255}, Wrap(kWrapClampToEdge, kWrapClampToEdge) | kLinearFilters);
  // Halfway between black and white is linear 0.5 (not sRGB 0.5, which is linear 0.214),
  // and alpha stays linear.
  glm::vec4 v = Lookup(tex, {0.5f, 0.5f}, 0.0f, true);
  EXPECT_EQ(v.r, 0.5f);
  EXPECT_EQ(v.a, 0.5f);
  RenderScene grey = OneTexture(1, 1, {128, 64, 200, 128}, 0u);
  EXPECT_EQ(Lookup(grey, {0.3f, 0.3f}, 0.0f, true), glm::vec4(table[128], table[64], table[200], Byte(128)));
}

TEST(TextureFilter, MipSelectionFollowsTheMinificationFilter) {
  using namespace shader;
  // 4 × 4, left half black and right half white: level 1 (2 × 2) is black | white, level 2
  // (1 × 1) grey. Read at u = 0.3, in the black half of levels 0 and 1.
  std::vector<uint8_t> bytes;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) bytes.insert(bytes.end(), {uint8_t(x < 2 ? 0 : 255), 0, 0, 255});
  const uint32_t clamp = Wrap(kWrapClampToEdge, kWrapClampToEdge);
  RenderScene trilinear = OneTexture(4, 4, bytes, clamp | kTextureMipLinear);
  EXPECT_EQ(trilinear.textures[0].mode >> kTextureLevelShift, 3u);
  EXPECT_EQ(Lookup(trilinear, {0.3f, 0.5f}, 1.0f).r, 0.0f);
  EXPECT_EQ(Lookup(trilinear, {0.3f, 0.5f}, 2.0f).r, Byte(128));
  EXPECT_EQ(Lookup(trilinear, {0.3f, 0.5f}, 9.0f).r, Byte(128));  // past the last level: the last
  EXPECT_EQ(Lookup(trilinear, {0.3f, 0.5f}, 1.25f).r, 0.25f * Byte(128));
  RenderScene nearestMip = OneTexture(4, 4, bytes, clamp | kTextureMipNearest);
  EXPECT_EQ(Lookup(nearestMip, {0.3f, 0.5f}, 1.4f).r, 0.0f);
  EXPECT_EQ(Lookup(nearestMip, {0.3f, 0.5f}, 1.6f).r, Byte(128));
  // Without a mipmap mode minification reads level 0, as does magnification (lod ≤ 0).
  RenderScene noMip = OneTexture(4, 4, bytes, clamp);
  EXPECT_EQ(Lookup(noMip, {0.6f, 0.5f}, 2.0f).r, 1.0f);
  EXPECT_EQ(Lookup(trilinear, {0.6f, 0.5f}, -3.0f).r, 1.0f);
  EXPECT_EQ(Lookup(trilinear, {0.6f, 0.5f}, NAN).r, 1.0f);
}

// Each level's mean (in linear space) equals level 0's, up to the rounding of each level
// to bytes, for sizes that halve evenly and sizes that do not. A filter averaging texels
// 2i and 2i + 1 (dropping an odd size's last column or row) fails it for 37 × 23 and
// 5 × 1 (checked).
TEST(TextureFilter, MipChainsConserveTheMean) {
  std::mt19937 rng(7);
  for (bool srgb : {false, true})
    for (glm::uvec2 size : {glm::uvec2(64, 32), glm::uvec2(37, 23), glm::uvec2(5, 1)}) {
      // Red ramps up from left to right (a filter that drops an odd size's last column
      // or row shifts its mean), the other channels are random.
      TextureImage im{"ramp", size.x, size.y, std::vector<uint8_t>(size_t(4) * size.x * size.y)};
      for (size_t i = 0; i < im.rgba.size(); ++i)
        im.rgba[i] = i % 4 == 0 ? uint8_t(255 * (i / 4 % size.x) / std::max(size.x - 1, 1u)) : uint8_t(rng() & 0xFF);
      const std::vector<std::vector<uint32_t>> chain = MipChain(im, srgb);
      ASSERT_EQ(chain.size(), 1 + uint32_t(std::log2(std::max(size.x, size.y))));
      EXPECT_EQ(chain.back().size(), 1u);
      const std::vector<float> table = TexelDecodeTable();
      auto mean = [&](const std::vector<uint32_t>& level, int c) {
        double sum = 0.0;
        for (uint32_t w : level)
          sum += srgb && c < 3 ? table[(w >> (8 * c)) & 0xFF] : shader::UnormByte((w >> (8 * c)) & 0xFF);
        return sum / double(level.size());
      };
      for (size_t l = 1; l < chain.size(); ++l)
        for (int c = 0; c < 4; ++c)
          EXPECT_NEAR(mean(chain[l], c), mean(chain[0], c), 0.6 / 255.0 * double(l))
              << size.x << "×" << size.y << (srgb ? " sRGB" : "") << " level " << l << " channel " << c;
    }
}

}  // namespace
}  // namespace vkpt::internal

// Decoding texture images (PNG, JPEG) that are well formed: every PNG colour type and bit
// depth with exact texel values, baseline, progressive and grey JPEGs, and real files of
// the corpus. The bad ones are in test_texture_decode_bad.cpp.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <thread>

#include "image/texture_decode.h"
#include "png_writer.h"
#include "test_util.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

using Bytes = std::vector<unsigned char>;
using Rgba = std::array<int, 4>;

Bytes FileBytes(const std::string& path) {
  const std::string text = test::ReadFile(path);
  return Bytes(text.begin(), text.end());
}

Rgba8Image Decode(const Bytes& bytes) { return DecodeTextureImage(bytes, ReadTextureImageHeader(bytes, "")); }

Rgba Texel(const Rgba8Image& image, uint32_t x, uint32_t y) {
  const uint8_t* t = &image.texels[(size_t(y) * image.width + x) * 4];
  return {t[0], t[1], t[2], t[3]};
}

// Every texel of a w × h image, row 0 first, against `expected`.
void ExpectTexels(const Rgba8Image& image, uint32_t w, uint32_t h, const std::vector<Rgba>& expected) {
  ASSERT_EQ(image.width, w);
  ASSERT_EQ(image.height, h);
  ASSERT_EQ(image.texels.size(), size_t(w) * h * 4);
  for (uint32_t i = 0; i < w * h; ++i) EXPECT_EQ(Texel(image, i % w, i / w), expected[i]) << "texel " << i;
}

TEST(TextureDecode, PngGreyEightBit) {
  const Bytes png = test::MakePng(3, 2, 8, 0, {0, 7, 128, 200, 254, 255});
  const TextureImageHeader header = ReadTextureImageHeader(png, "image/png");
  EXPECT_EQ(header.format, "PNG");
  EXPECT_EQ(header.channels, 1u);
  EXPECT_FALSE(header.sixteenBit);
  ExpectTexels(DecodeTextureImage(png, header), 3, 2,
               {{0, 0, 0, 255},
                {7, 7, 7, 255},
                {128, 128, 128, 255},
                {200, 200, 200, 255},
                {254, 254, 254, 255},
                {255, 255, 255, 255}});
}

TEST(TextureDecode, PngGreyAlpha) {
  const Bytes png = test::MakePng(2, 2, 8, 4, {10, 0, 20, 128, 30, 255, 40, 77});
  EXPECT_EQ(ReadTextureImageHeader(png, "").channels, 2u);
  ExpectTexels(Decode(png), 2, 2, {{10, 10, 10, 0}, {20, 20, 20, 128}, {30, 30, 30, 255}, {40, 40, 40, 77}});
}

TEST(TextureDecode, PngRgb) {
  const Bytes png = test::MakePng(2, 2, 8, 2, {255, 0, 0, 0, 255, 0, 0, 0, 255, 1, 2, 3});
  EXPECT_EQ(ReadTextureImageHeader(png, "").channels, 3u);
  ExpectTexels(Decode(png), 2, 2, {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {1, 2, 3, 255}});
}

TEST(TextureDecode, PngRgbaRowZeroIsTheTop) {
  const Bytes png = test::MakePng(1, 3, 8, 6, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12});
  EXPECT_EQ(ReadTextureImageHeader(png, "").channels, 4u);
  ExpectTexels(Decode(png), 1, 3, {{1, 2, 3, 4}, {5, 6, 7, 8}, {9, 10, 11, 12}});
}

TEST(TextureDecode, PngPaletteWithAndWithoutTransparency) {
  const test::PngChunk palette{"PLTE", {255, 0, 0, 0, 128, 0, 10, 20, 30}};
  // Two-bit indices 0, 1, 2, 1 packed in one byte per row of four.
  const Bytes opaque = test::MakePng(4, 1, 2, 3, {0b00011001}, {palette});
  EXPECT_EQ(ReadTextureImageHeader(opaque, "").channels, 3u);
  ExpectTexels(Decode(opaque), 4, 1, {{255, 0, 0, 255}, {0, 128, 0, 255}, {10, 20, 30, 255}, {0, 128, 0, 255}});
  // tRNS gives the first two entries alpha; the third stays opaque.
  const Bytes alpha = test::MakePng(3, 1, 8, 3, {2, 1, 0}, {palette, {"tRNS", {0, 99}}});
  EXPECT_EQ(ReadTextureImageHeader(alpha, "").channels, 4u);
  ExpectTexels(Decode(alpha), 3, 1, {{10, 20, 30, 255}, {0, 128, 0, 99}, {255, 0, 0, 0}});
}

// All 65536 16-bit grey values, checked against round(v·255/65535) computed in floating
// point (never a tie: v·510 is even, 65535·(2k+1) odd), which the integer formula must match.
TEST(TextureDecode, PngSixteenBitGreyEveryValue) {
  std::vector<uint8_t> samples;
  for (uint32_t v = 0; v < 65536; ++v) samples.insert(samples.end(), {uint8_t(v >> 8), uint8_t(v)});
  const Bytes png = test::MakePng(256, 256, 16, 0, samples);
  const TextureImageHeader header = ReadTextureImageHeader(png, "");
  EXPECT_TRUE(header.sixteenBit);
  EXPECT_EQ(header.channels, 1u);
  const Rgba8Image image = DecodeTextureImage(png, header);
  ASSERT_EQ(image.texels.size(), 65536u * 4);
  for (uint32_t v = 0; v < 65536; ++v) {
    const int g = int(std::lround(v * 255.0 / 65535.0));
    ASSERT_EQ(Texel(image, v % 256, v / 256), (Rgba{g, g, g, 255})) << "value " << v;
  }
}

TEST(TextureDecode, PngSixteenBitRgbaAndGreyAlpha) {
  // 32767 → 127.498…, 32768 → 127.502… (round down, then up); 257·k → k exactly.
  const Bytes rgba = test::MakePng(1, 1, 16, 6, {0x7f, 0xff, 0x80, 0x00, 0x01, 0x01, 0xff, 0xff});
  EXPECT_EQ(ReadTextureImageHeader(rgba, "").channels, 4u);
  ExpectTexels(Decode(rgba), 1, 1, {{127, 128, 1, 255}});
  const Bytes greyAlpha = test::MakePng(1, 1, 16, 4, {0x00, 0x80, 0x12, 0x34});
  ExpectTexels(Decode(greyAlpha), 1, 1, {{0, 0, 0, (0x1234 * 255 + 32767) / 65535}});
}

const std::string kFixtures = test::SourcePath("tests/data/textures/");

// The quadrant colours of the fixtures (tests/data/textures/README.md), within what JPEG
// at quality 95 with 4:2:0 chroma keeps, at each quadrant's centre.
void ExpectQuadrants(const Rgba8Image& image, bool grey) {
  ASSERT_EQ(image.width, 20u);
  ASSERT_EQ(image.height, 12u);
  const std::array<Rgba, 4> colours = {
      {{200, 30, 30, 255}, {30, 180, 40, 255}, {40, 60, 210, 255}, {240, 240, 240, 255}}};
  for (int q = 0; q < 4; ++q) {
    const Rgba texel = Texel(image, q % 2 ? 15 : 5, q / 2 ? 9 : 3);
    Rgba want = colours[q];
    if (grey) {
      const int luma = int(std::lround(0.299 * want[0] + 0.587 * want[1] + 0.114 * want[2]));
      want = {luma, luma, luma, 255};
    }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(texel[c], want[c], 6) << "quadrant " << q << " channel " << c;
    EXPECT_EQ(texel[3], 255);
    if (grey) {
      EXPECT_TRUE(texel[0] == texel[1] && texel[1] == texel[2]);
    }
  }
}

TEST(TextureDecode, BaselineAndGreyJpeg) {
  const Bytes baseline = FileBytes(kFixtures + "quadrants-baseline.jpg");
  const TextureImageHeader header = ReadTextureImageHeader(baseline, "image/jpeg");
  EXPECT_EQ(header.format, "JPEG");
  EXPECT_EQ(header.channels, 3u);
  EXPECT_FALSE(header.sixteenBit);
  ExpectQuadrants(DecodeTextureImage(baseline, header), false);
  const Bytes grey = FileBytes(kFixtures + "quadrants-grey.jpg");
  EXPECT_EQ(ReadTextureImageHeader(grey, "").channels, 1u);
  ExpectQuadrants(Decode(grey), true);
}

// jpegtran made the progressive file from the baseline one without requantizing, so the
// texels must be the same bytes.
TEST(TextureDecode, ProgressiveJpegEqualsItsBaseline) {
  const Rgba8Image progressive = Decode(FileBytes(kFixtures + "quadrants-progressive.jpg"));
  ExpectQuadrants(progressive, false);
  EXPECT_EQ(progressive.texels, Decode(FileBytes(kFixtures + "quadrants-baseline.jpg")).texels);
}

// Real files of the test data (test_util.h): palette PNGs of 1 and 8 bits, RGBA, a 2048 × 2048
// baseline JPEG.
TEST(TextureDecode, CorpusImages) {
  VKPT_REQUIRE_SHARED_DATA();
  const std::string pbr = test::SharedData("gltf-pbr/");
  const struct {
    std::string path;
    uint32_t width, height, channels;
  } files[] = {
      {test::CorpusPath("valid/BoxTexturedNonPowerOfTwo/glTF/CesiumLogoFlat.png"), 211, 211, 3},
      {test::CorpusPath("valid/Cube/glTF/Cube_MetallicRoughness.png"), 512, 512, 3},
      {pbr + "TextureTransformTest/glTF/UV.png", 256, 256, 4},
      {pbr + "LightsPunctualLamp/glTF/material0_emissive.jpeg", 2048, 2048, 3},
  };
  for (const auto& file : files) {
    SCOPED_TRACE(file.path);
    ASSERT_TRUE(std::filesystem::exists(file.path)) << "missing";
    const Bytes bytes = FileBytes(file.path);
    const TextureImageHeader header = ReadTextureImageHeader(bytes, "");
    EXPECT_EQ(header.width, file.width);
    EXPECT_EQ(header.height, file.height);
    EXPECT_EQ(header.channels, file.channels);
    const Rgba8Image image = DecodeTextureImage(bytes, header);
    EXPECT_EQ(image.texels.size(), size_t(file.width) * file.height * 4);
  }
}

// stb's failure reason is a global: decodes on several threads at once must neither race
// nor mix up their results or messages.
TEST(TextureDecode, SeveralThreadsAtOnce) {
  const Bytes jpeg = FileBytes(kFixtures + "quadrants-progressive.jpg");
  const std::vector<uint8_t> expected = Decode(jpeg).texels;
  Bytes broken = test::MakePng(4, 4, 8, 0, std::vector<uint8_t>(16, 9));
  broken[test::PngChunkData(broken, "IDAT")] ^= 0x40;  // the zlib header: its check bits no longer hold
  std::vector<std::string> results(4);
  std::vector<std::thread> threads;
  for (size_t t = 0; t < results.size(); ++t)
    threads.emplace_back([&, t] {
      for (int i = 0; i < 50; ++i) {
        if (t % 2) {
          if (Decode(jpeg).texels != expected) results[t] = "wrong texels";
        } else {
          try {
            Decode(broken);
            results[t] = "decoded a corrupt PNG";
          } catch (const Error& e) {
            if (std::string(e.what()).find("zlib") == std::string::npos) results[t] = e.what();
          }
        }
      }
    });
  for (std::thread& thread : threads) thread.join();
  for (const std::string& result : results) EXPECT_EQ(result, "");
}

}  // namespace
}  // namespace vkpt::internal

// WebP textures (image/webp_decode.h, EXT_texture_webp) and KTX2 ones (KHR_texture_basisu,
// which vkpt cannot decode): a lossless WebP decodes to the texels of a PNG of the same
// image; a WebP cut anywhere, or animated, is refused; EXT_texture_webp's image wins over
// the texture's fallback; a KTX2 texture uses its fallback, or is an error naming the
// extension and the texture. CesiumBoxWebp of ../shared/gltf-ext loads with nothing ignored.
#include <gtest/gtest.h>

#include <webp/encode.h>

#include <string>
#include <vector>

#include "gltf/gltf_loader.h"
#include "gltf_builder.h"
#include "image/texture_decode.h"
#include "png_writer.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

using namespace test;
using Texels = std::vector<unsigned char>;

// A 37 × 23 RGBA image: gradients in R and G, a checker in B, alpha falling along x.
Texels Pattern(uint32_t w = 37, uint32_t h = 23) {
  Texels rgba;
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x)
      rgba.insert(rgba.end(), {uint8_t(x * 255 / (w - 1)), uint8_t(y * 255 / (h - 1)),
                               uint8_t((x / 4 + y / 4) % 2 ? 200 : 30), uint8_t(255 - x * 5)});
  return rgba;
}

Texels LosslessWebp(const Texels& rgba, uint32_t w = 37, uint32_t h = 23) {
  uint8_t* out = nullptr;
  const size_t size = WebPEncodeLosslessRGBA(rgba.data(), int(w), int(h), int(w * 4), &out);
  Texels webp(out, out + size);
  WebPFree(out);
  return webp;
}

std::string ErrorOf(const Texels& bytes) {
  try {
    DecodeTextureImage(bytes, ReadTextureImageHeader(bytes, "image/webp"));
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Webp, LosslessDecodesToThePngsTexels) {
  const Texels rgba = Pattern(), webp = LosslessWebp(rgba), png = MakePng(37, 23, 8, 6, rgba);
  const TextureImageHeader header = ReadTextureImageHeader(webp, "image/webp");
  EXPECT_EQ(header.format, "WebP");
  EXPECT_EQ(header.width, 37u);
  EXPECT_EQ(header.height, 23u);
  EXPECT_EQ(header.channels, 4u);
  const Rgba8Image fromWebp = DecodeTextureImage(webp, header);
  const Rgba8Image fromPng = DecodeTextureImage(png, ReadTextureImageHeader(png, "image/png"));
  EXPECT_EQ(fromWebp.texels, fromPng.texels);
  EXPECT_EQ(fromWebp.texels, rgba);
}

TEST(Webp, CutAnywhereOrAnimatedIsRefused) {
  const Texels webp = LosslessWebp(Pattern());
  size_t refused = 0;
  for (size_t cut = 1; cut < webp.size(); ++cut) {
    const std::string e = ErrorOf(Texels(webp.begin(), webp.begin() + cut));
    refused += e != "(no error)";
    EXPECT_LT(e.size(), 160u) << e;
  }
  std::printf("%zu of %zu cuts of a %zu-byte WebP refused\n", refused, webp.size() - 1, webp.size());
  EXPECT_EQ(refused, webp.size() - 1);
  EXPECT_EQ(ErrorOf(Texels(webp.begin(), webp.begin() + 20)).rfind("is truncated (WebP: its RIFF header declares", 0),
            0u);
  // An extended header (VP8X) whose flags say "animation": 16 × 16, nothing else needed.
  const Texels animated = {'R', 'I', 'F', 'F', 22, 0, 0, 0, 'W', 'E', 'B', 'P', 'V', 'P', '8',
                           'X', 10,  0,   0,   0,  2, 0, 0, 0,   15,  0,   0,   15,  0,   0};
  EXPECT_EQ(ErrorOf(animated), "is an animated WebP; a texture must be a still image");
}

// A textured triangle whose texture names image 0 (a 1 × 1 PNG, blue) as its `source` and
// image 1 in `extension` ("EXT_texture_webp": a 1 × 1 WebP, red; "KHR_texture_basisu": a
// stand-in for KTX2 bytes). `fallback`: whether the texture keeps its `source`.
GltfBuilder TexturedByExtension(const std::string& extension, bool fallback, bool required) {
  GltfBuilder b;
  const int positions = b.Positions(kUnitTriangle);
  const int uv = b.Accessor(b.View(Bytes(std::vector<float>{0, 0, 1, 0, 0, 1})), kFloat, 3, "VEC2");
  b.meshes.push_back(R"({"primitives":[{"attributes":{"POSITION":)" + std::to_string(positions) + R"(,"TEXCOORD_0":)" +
                     std::to_string(uv) + R"(},"material":0}]})");
  b.materials.push_back(R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}})");
  const Texels png = MakePng(1, 1, 8, 6, {0, 0, 255, 255}), webp = LosslessWebp({255, 0, 0, 255}, 1, 1);
  const Texels other = extension == "EXT_texture_webp" ? webp : Texels{0xab, 'K', 'T', 'X', ' ', '2', '0', 0xbb};
  b.images.push_back(R"({"bufferView":)" + std::to_string(b.View(std::string(png.begin(), png.end()))) +
                     R"(,"mimeType":"image/png"})");
  b.images.push_back(R"({"bufferView":)" + std::to_string(b.View(std::string(other.begin(), other.end()))) +
                     R"(,"mimeType":")" + (extension == "EXT_texture_webp" ? "image/webp" : "image/ktx2") + "\"}");
  b.textures.push_back(std::string("{") + (fallback ? R"("source":0,)" : "") + R"("extensions":{")" + extension +
                       R"(":{"source":1}}})");
  b.Node(R"({"mesh":0})");
  b.extensionsUsed = {extension};
  if (required) b.extensionsRequired = {extension};
  return b;
}

TEST(Webp, ExtensionImageWinsOverTheFallback) {
  for (bool fallback : {true, false}) {
    const Scene s = Load(TexturedByExtension("EXT_texture_webp", fallback, !fallback));
    ASSERT_EQ(s.images.size(), 1u);
    EXPECT_EQ(s.images[0].rgba, (std::vector<uint8_t>{255, 0, 0, 255})) << "fallback " << fallback;
    EXPECT_TRUE(s.ignoredFeatures.empty()) << s.ignoredFeatures.front();
  }
}

TEST(Webp, Ktx2TexturesUseTheirFallbackOrAreNamed) {
  const Scene s = Load(TexturedByExtension("KHR_texture_basisu", true, false));
  ASSERT_EQ(s.images.size(), 1u);
  EXPECT_EQ(s.images[0].rgba, (std::vector<uint8_t>{0, 0, 255, 255}));
  ASSERT_EQ(s.ignoredFeatures.size(), 1u);
  EXPECT_EQ(s.ignoredFeatures[0],
            "extension KHR_texture_basisu: KTX2 images are not decoded; each texture's fallback image is used");
  EXPECT_TRUE(FailsWith(TexturedByExtension("KHR_texture_basisu", false, true),
                        {"materials[0]", "baseColorTexture: textures[0] has only a KHR_texture_basisu (KTX2) image",
                         "no PNG, JPEG or WebP source to fall back on"}));
}

TEST(Webp, CesiumBoxWebpLoadsWithNothingIgnored) {
  VKPT_REQUIRE_SHARED_DATA();
  const Scene s = LoadGltf(SharedData("gltf-ext/CesiumBoxWebp/glTF/CesiumBoxWebp-Required.gltf"));
  ASSERT_EQ(s.images.size(), 1u);
  EXPECT_EQ(s.triangles.size(), 12u);
  EXPECT_TRUE(s.ignoredFeatures.empty()) << s.ignoredFeatures.front();
  std::printf("CesiumBoxWebp: a %u × %u WebP texture\n", s.images[0].width, s.images[0].height);
}

}  // namespace
}  // namespace vkpt::internal

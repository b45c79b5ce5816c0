// Texture images as untrusted input: every bad image is a Error with a short message
// that reads well after the caller's "scene.gltf: images[3] ... : " prefix, never a crash,
// a hang, a large allocation or a success. Cuts and corruptions are tried at every byte
// of small files, so that no position escapes (run under ASan for out-of-bounds reads).
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <initializer_list>

#include "image/texture_decode.h"
#include "png_writer.h"
#include "test_util.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

using Bytes = std::vector<unsigned char>;

Bytes FileBytes(const std::string& path) {
  const std::string text = test::ReadFile(path);
  return Bytes(text.begin(), text.end());
}

// The message `run` fails with; "(no error)" if it succeeds.
std::string ErrorOf(const std::function<void()>& run) {
  try {
    run();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

std::string HeaderError(const Bytes& bytes, std::string_view mime = "") {
  return ErrorOf([&] { ReadTextureImageHeader(bytes, mime); });
}

// Where `pattern` first occurs in `bytes` (bytes.size() if nowhere).
size_t Find(const Bytes& bytes, std::initializer_list<unsigned char> pattern) {
  return size_t(std::search(bytes.begin(), bytes.end(), pattern.begin(), pattern.end()) - bytes.begin());
}

const std::string kFixtures = test::SourcePath("tests/data/textures/");

// A PNG with more than one row and chunk kind to cut: 8 × 4 RGBA with a tEXt chunk.
Bytes SmallPng() { return test::MakePng(8, 4, 8, 6, std::vector<uint8_t>(8 * 4 * 4, 77), {{"tEXt", {'a', 0, 'b'}}}); }

TEST(TextureDecode, EmptyInput) {
  EXPECT_EQ(HeaderError({}, "image/png"), "is empty (0 bytes)");
  EXPECT_EQ(ErrorOf([] { DecodeTextureImage({}, TextureImageHeader{1, 1, 4, false, "PNG"}); }), "is empty (0 bytes)");
}

TEST(TextureDecode, UnknownFormatNamesTheMimeType) {
  const Bytes avif = {0, 0, 0, 0x1c, 'f', 't', 'y', 'p', 'a', 'v', 'i', 'f'};
  EXPECT_EQ(HeaderError(avif, "image/avif"),
            "is not PNG, JPEG or WebP (mimeType \"image/avif\", first bytes 00 00 00 1C)");
  const Bytes ktx2 = {0xab, 'K', 'T', 'X', ' ', '2', '0', 0xbb, '\r', '\n', 0x1a, '\n'};
  EXPECT_EQ(HeaderError(ktx2, "image/ktx2"),
            "is not PNG, JPEG or WebP (mimeType \"image/ktx2\", first bytes AB 4B 54 58)");
  // The mimeType does not decide: a PNG called JPEG is still read as PNG, and the reverse.
  EXPECT_EQ(ReadTextureImageHeader(SmallPng(), "image/jpeg").format, "PNG");
  EXPECT_EQ(HeaderError({0x89, 'P'}), "is not PNG, JPEG or WebP (no mimeType, first bytes 89 50)");
}

TEST(TextureDecode, SidesAbove16384RefusedFromTheHeader) {
  EXPECT_EQ(HeaderError(test::MakePng(20000, 300, 8, 0, {})),
            "is 20000 × 300 pixels; a texture may be at most 16384 on each side");
  EXPECT_EQ(HeaderError(test::MakePng(300, 16385, 8, 0, {})),
            "is 300 × 16385 pixels; a texture may be at most 16384 on each side");
  EXPECT_EQ(HeaderError(test::MakePng(0, 5, 8, 0, {})),
            "is 0 × 5 pixels; a texture needs at least one pixel on each side");
  // 16384 itself is allowed, and decodes.
  const Bytes widest = test::MakePng(16384, 1, 8, 0, std::vector<uint8_t>(16384, 3));
  EXPECT_EQ(DecodeTextureImage(widest, ReadTextureImageHeader(widest, "")).texels.size(), 16384u * 4);
  // A JPEG's frame header, patched to 20000 wide.
  Bytes jpeg = FileBytes(kFixtures + "quadrants-baseline.jpg");
  const size_t sof = Find(jpeg, {0xff, 0xc0});
  ASSERT_LT(sof, jpeg.size());
  jpeg[sof + 7] = 20000 >> 8;
  jpeg[sof + 8] = 20000 & 0xff;
  EXPECT_EQ(HeaderError(jpeg), "is 20000 × 12 pixels; a texture may be at most 16384 on each side");
}

// A tiny PNG whose IHDR claims 60000 × 60000 RGBA (14 GB decoded): refused from its header,
// before stb could allocate for it, and by the decoder too if handed a header that lies.
TEST(TextureDecode, BombRefusedBeforeDecoding) {
  const Bytes bomb = test::MakePng(60000, 60000, 8, 6, std::vector<uint8_t>(64, 0));
  ASSERT_LT(bomb.size(), 200u);
  EXPECT_EQ(HeaderError(bomb), "is 60000 × 60000 pixels; a texture may be at most 16384 on each side");
  EXPECT_EQ(ErrorOf([&] {
              DecodeTextureImage(bomb, TextureImageHeader{60000, 60000, 4, false, "PNG"});
            }),
            "is 60000 × 60000 pixels; a texture may be at most 16384 on each side");
}

// Every cut of a PNG, down to the last byte of IEND's CRC: refused by the header, and by
// the decoder given the uncut file's header.
TEST(TextureDecode, TruncatedPngAtEveryByte) {
  const Bytes png = SmallPng();
  const TextureImageHeader header = ReadTextureImageHeader(png, "");
  for (size_t cut = 1; cut < png.size(); ++cut) {
    SCOPED_TRACE("cut at " + std::to_string(cut) + " of " + std::to_string(png.size()));
    const Bytes part(png.begin(), png.begin() + cut);
    const std::string byHeader = HeaderError(part), byDecoder = ErrorOf([&] { DecodeTextureImage(part, header); });
    if (cut < 8) {
      EXPECT_NE(byHeader.find("is not PNG, JPEG or WebP"), std::string::npos) << byHeader;
      EXPECT_NE(byDecoder, "(no error)");
    } else {
      EXPECT_EQ(byHeader.rfind("is truncated (PNG: ", 0), 0u) << byHeader;
      EXPECT_EQ(byDecoder.rfind("is truncated (PNG: ", 0), 0u) << byDecoder;
    }
    EXPECT_LT(byHeader.size(), 160u);
  }
}

// Every cut of the three JPEG fixtures: the structure walk refuses each, from the header
// and again in the decoder given the uncut file's header (stb alone would say "expected
// marker" or the like, or be handed zeros for the missing data).
TEST(TextureDecode, TruncatedJpegAtEveryByte) {
  for (const char* name : {"quadrants-baseline.jpg", "quadrants-progressive.jpg", "quadrants-grey.jpg"}) {
    const Bytes jpeg = FileBytes(kFixtures + name);
    const TextureImageHeader header = ReadTextureImageHeader(jpeg, "");
    for (size_t cut = 1; cut < jpeg.size(); ++cut) {
      SCOPED_TRACE(std::string(name) + " cut at " + std::to_string(cut));
      const Bytes part(jpeg.begin(), jpeg.begin() + cut);
      const std::string byHeader = HeaderError(part), byDecoder = ErrorOf([&] { DecodeTextureImage(part, header); });
      const std::string expected = cut < 3 ? "is not PNG, JPEG or WebP" : "is truncated (JPEG: ";
      EXPECT_EQ(byHeader.rfind(expected, 0), 0u) << byHeader;
      EXPECT_EQ(byDecoder, byHeader);
      EXPECT_LT(byHeader.size(), 160u);
    }
  }
}

TEST(TextureDecode, TruncatedCorpusJpeg) {
  VKPT_REQUIRE_SHARED_DATA();
  const Bytes jpeg = FileBytes(test::SharedData("gltf-pbr/LightsPunctualLamp/glTF/material0_emissive.jpeg"));
  ASSERT_GT(jpeg.size(), 1000u);
  const TextureImageHeader header = ReadTextureImageHeader(jpeg, "");
  for (size_t cut : {jpeg.size() / 2, jpeg.size() - 2, jpeg.size() - 1}) {
    const Bytes part(jpeg.begin(), jpeg.begin() + cut);
    EXPECT_EQ(ErrorOf([&] { DecodeTextureImage(part, header); }), "is truncated (JPEG: it ends inside its image data)");
  }
}

// Each byte of the file inverted in turn: an error, or an image of the declared size;
// never a crash or an out-of-bounds access (the sanitizer build checks that).
void CorruptEveryByte(const Bytes& original) {
  size_t decoded = 0, refused = 0;
  for (size_t at = 0; at < original.size(); ++at) {
    Bytes bytes = original;
    bytes[at] ^= 0xff;
    try {
      const TextureImageHeader header = ReadTextureImageHeader(bytes, "");
      const Rgba8Image image = DecodeTextureImage(bytes, header);
      ASSERT_EQ(image.texels.size(), size_t(header.width) * header.height * 4) << "byte " << at;
      ++decoded;
    } catch (const Error& e) {
      EXPECT_LT(std::string(e.what()).size(), 200u) << e.what();
      ++refused;
    }
  }
  // Both outcomes happen, or the test would not be telling much.
  EXPECT_GT(decoded, 0u);
  EXPECT_GT(refused, 0u);
}

TEST(TextureDecode, CorruptPngBytes) { CorruptEveryByte(SmallPng()); }

// Real deflate streams: a palette image, and RGBA.
TEST(TextureDecode, CorruptCorpusPngBytes) {
  VKPT_REQUIRE_SHARED_DATA();
  CorruptEveryByte(FileBytes(test::CorpusPath("valid/BoxTexturedNonPowerOfTwo/glTF/CesiumLogoFlat.png")));
  CorruptEveryByte(FileBytes(test::SharedData("gltf-pbr/TextureTransformTest/glTF/Arrow.png")));
}

TEST(TextureDecode, CorruptJpegBytes) {
  for (const char* name : {"quadrants-baseline.jpg", "quadrants-progressive.jpg", "quadrants-grey.jpg"})
    CorruptEveryByte(FileBytes(kFixtures + name));
}

TEST(TextureDecode, MalformedHeaders) {
  Bytes rgb4 = test::MakePng(1, 1, 8, 2, {1, 2, 3});
  rgb4[24] = 4;  // bit depth
  EXPECT_EQ(HeaderError(rgb4), "is corrupt (PNG: colour type 2 with 4-bit samples)");
  const Bytes noIhdr = [] {
    Bytes png = test::MakePng(1, 1, 8, 0, {1});
    png[12] = 'X';
    return png;
  }();
  EXPECT_EQ(HeaderError(noIhdr), "is corrupt (PNG: its first chunk is not a 13-byte IHDR)");
  // The corpus's invalid_image_data.jpg, all 16 bytes of it: SOI, then 0xFF and zeros.
  Bytes zeros(16, 0);
  zeros[0] = 0xff, zeros[1] = 0xd8, zeros[2] = 0xff;
  EXPECT_EQ(HeaderError(zeros), "is corrupt (JPEG: a segment at byte 2 declares a length below 2)");

  const Bytes jpeg = FileBytes(kFixtures + "quadrants-baseline.jpg");
  const size_t sof = Find(jpeg, {0xff, 0xc0});
  ASSERT_LT(sof, jpeg.size());
  Bytes arithmetic = jpeg, twelveBit = jpeg, twoComponents = jpeg;
  arithmetic[sof + 1] = 0xc9;
  EXPECT_EQ(HeaderError(arithmetic),
            "is a JPEG coded in a way stb_image cannot decode (frame marker FF C9: lossless, hierarchical or "
            "arithmetic); only baseline and progressive JPEGs are supported");
  twelveBit[sof + 4] = 12;
  EXPECT_EQ(HeaderError(twelveBit), "is a JPEG with 12-bit samples; only 8-bit JPEGs are supported");
  twoComponents[sof + 9] = 2;
  EXPECT_EQ(HeaderError(twoComponents), "is a JPEG with 2 colour components; 1, 3 or 4 are supported");
  // More than 256 codes in a Huffman table: stb 2.27 would write past its tables.
  Bytes manyCodes = jpeg;
  const size_t dht = Find(manyCodes, {0xff, 0xc4});
  ASSERT_LT(dht, jpeg.size());
  std::fill_n(manyCodes.begin() + dht + 5, 16, 255);
  const std::string tooMany = "is corrupt (JPEG: the Huffman table at byte " + std::to_string(dht + 4) +
                              " declares 4080 codes; at most 256 exist)";
  EXPECT_EQ(HeaderError(manyCodes), tooMany);
  EXPECT_EQ(ErrorOf([&] { DecodeTextureImage(manyCodes, ReadTextureImageHeader(jpeg, "")); }), tooMany);
  // Chunk types stb would name in a buffer shared by all threads, refused before it runs.
  const Bytes good = test::MakePng(1, 1, 8, 0, {1});
  const TextureImageHeader header = ReadTextureImageHeader(good, "");
  for (const auto& [type, message] :
       {std::pair<std::string, std::string>{"ZZZZ", "unknown critical chunk ZZZZ at byte 33"},
        {"zz1z", "the chunk at byte 33 has a type that is not four letters"}}) {
    const Bytes png = test::MakePng(1, 1, 8, 0, {1}, {{type, {1, 2}}});
    EXPECT_EQ(HeaderError(png), "is corrupt (PNG: " + message + ")");
    EXPECT_EQ(ErrorOf([&] { DecodeTextureImage(png, header); }), "is corrupt (PNG: " + message + ")");
  }
  // An unknown ancillary chunk (lower-case first letter) is skipped.
  const Bytes ancillary = test::MakePng(1, 1, 8, 0, {1}, {{"zzZz", {1, 2}}});
  EXPECT_EQ(DecodeTextureImage(ancillary, ReadTextureImageHeader(ancillary, "")).texels.size(), 4u);
  // A header that belongs to another format.
  EXPECT_EQ(ErrorOf([&] {
              DecodeTextureImage(jpeg, TextureImageHeader{20, 12, 3, false, "PNG"});
            }),
            "is a 20 × 12 JPEG, not the 20 × 12 PNG its header said");
}

}  // namespace
}  // namespace vkpt::internal

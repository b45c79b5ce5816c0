// Decoding the images glTF textures use (PNG, JPEG and, with EXT_texture_webp, WebP) into
// RGBA8 texels. The bytes are
// untrusted (docs/security.md): the format comes from the signature, the header is read
// and its dimensions checked before anything is decoded, and a truncated or corrupt image
// is a Error, never a crash, a hang or a success. Safe to call from several threads
// at once (stb_image is compiled privately here and none of its global settings is used).
//
// Error messages describe only the problem ("is truncated …", "is 20000 × 300 pixels; …"):
// the caller prefixes them with the scene file, the image and the material using it.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vkpt::internal {

// The largest width or height of a texture image (lavapipe's maxImageDimension2D).
constexpr uint32_t kMaxTextureSide = 16384;

// What an encoded image is, from its signature and header alone (nothing decoded).
struct TextureImageHeader {
  uint32_t width = 0, height = 0;
  // As stored: 1 grey, 2 grey+alpha, 3 RGB, 4 RGBA. A palette PNG counts as RGB, or RGBA
  // when it has a tRNS chunk; a CMYK JPEG as RGB (what stb converts it to).
  uint32_t channels = 0;
  bool sixteenBit = false;  // 16 bits per channel (PNG only)
  std::string format;       // "PNG", "JPEG" or "WebP"
};

// Decoded texels: RGBA8, row-major, row 0 = the first row of the file (the top; glTF's
// UV (0,0)), 4·width·height bytes.
struct Rgba8Image {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> texels;
};

// Identifies the format by its signature (not by mimeType, which is used only in the
// message when the bytes are not PNG, JPEG or WebP), reads the header, checks
// 1 <= width, height <= kMaxTextureSide. It also walks the whole file's structure (PNG
// chunks, JPEG segments and scans), so an image cut short, or one with parts that would
// trip stb (a JPEG Huffman table of more than 256 codes, an unknown critical PNG chunk),
// is refused here already. Throws Error on any problem.
TextureImageHeader ReadTextureImageHeader(std::span<const unsigned char> bytes, std::string_view mimeType);

// Decodes an image whose header ReadTextureImageHeader accepted (it walks the file again,
// so bytes that do not match `header` are refused too). Grey → (g,g,g,255),
// grey+alpha → (g,g,g,a), RGB → (r,g,b,255); a PNG's tRNS colour key becomes alpha.
// 16-bit channels become 8-bit by round(v·255/65535), exactly: (v*255 + 32767) / 65535.
// Throws Error for a truncated or corrupt image. Besides the result, stb needs
// working memory of up to about three times its size while it decodes (a progressive
// JPEG keeps every coefficient; a PNG its inflated rows and a 16-bit copy).
Rgba8Image DecodeTextureImage(std::span<const unsigned char> bytes, const TextureImageHeader& header);

}  // namespace vkpt::internal

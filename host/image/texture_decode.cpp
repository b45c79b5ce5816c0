#include "image/texture_decode.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

// Only the PNG and JPEG decoders, with internal linkage: Debian's tinygltf links its own
// stb_image, and image_load.cpp has another private copy for Radiance files.
#include "image/stb_source.h"
#include "image/webp_decode.h"
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO
#define STBI_MAX_DIMENSIONS 16384
#include <stb_image.h>

#include "util/error.h"

static_assert(STBI_MAX_DIMENSIONS == vkpt::internal::kMaxTextureSide);
// stb keeps its failure reason in a global; in C++ it is thread_local, so that concurrent
// decodes do not read each other's messages. Without it the messages could be wrong.
#ifndef STBI_THREAD_LOCAL
#error "stb_image's failure reason is not thread-local here"
#endif

namespace vkpt::internal {
namespace {

static_assert(sizeof(stbi__context::buffer_start) == StbSource::kRefillSize);
constexpr stbi_io_callbacks kStbCallbacks{&StbSource::Read, &StbSource::Skip, &StbSource::Eof};

constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

bool IsPng(std::span<const unsigned char> b) {
  return b.size() >= sizeof(kPngSignature) && std::equal(std::begin(kPngSignature), std::end(kPngSignature), b.begin());
}
// SOI and the 0xFF of the marker after it.
bool IsJpeg(std::span<const unsigned char> b) { return b.size() >= 3 && b[0] == 0xff && b[1] == 0xd8 && b[2] == 0xff; }

uint32_t Be16(std::span<const unsigned char> b, size_t at) { return uint32_t(b[at]) << 8 | b[at + 1]; }
uint32_t Be32(std::span<const unsigned char> b, size_t at) { return Be16(b, at) << 16 | Be16(b, at + 2); }

[[noreturn]] void Truncated(const std::string& detail) { throw Error("is truncated (" + detail + ")"); }
[[noreturn]] void Corrupt(const std::string& detail) { throw Error("is corrupt (" + detail + ")"); }

void CheckSize(uint32_t width, uint32_t height) {
  const std::string size = std::to_string(width) + " × " + std::to_string(height) + " pixels";
  if (width == 0 || height == 0) throw Error("is " + size + "; a texture needs at least one pixel on each side");
  if (width > kMaxTextureSide || height > kMaxTextureSide)
    throw Error("is " + size + "; a texture may be at most " + std::to_string(kMaxTextureSide) + " on each side");
}

// A chunk type as text for a message: four letters, or "?" for bytes that are none.
std::string ChunkName(std::span<const unsigned char> b, size_t at) {
  std::string name(b.begin() + at, b.begin() + at + 4);
  for (char c : name)
    if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'))) return "?";
  return name;
}

struct PngChunks {
  bool trns = false;  // a tRNS chunk precedes the image data (a palette image then has alpha)
  uint64_t idat = 0;  // bytes of compressed image data
};

// Walks a PNG's chunks from the signature to IEND, so that a file cut anywhere is refused
// before decoding, with a message that says where.
PngChunks WalkPngChunks(std::span<const unsigned char> b) {
  PngChunks chunks;
  bool data = false;
  for (size_t at = sizeof(kPngSignature);;) {
    if (b.size() - at < 12) Truncated("PNG: it ends at byte " + std::to_string(b.size()) + ", before its IEND chunk");
    const uint32_t length = Be32(b, at);
    const std::string name = ChunkName(b, at + 4);
    if (name == "?") Corrupt("PNG: the chunk at byte " + std::to_string(at) + " has a type that is not four letters");
    // stb reports an unknown critical chunk (an upper-case first letter) by writing its name
    // into one static buffer that all threads share: refusing them here keeps decodes off it.
    if (name[0] <= 'Z' && name != "IHDR" && name != "PLTE" && name != "IDAT" && name != "IEND")
      Corrupt("PNG: unknown critical chunk " + name + " at byte " + std::to_string(at));
    if (length > 0x7fffffffu)
      Corrupt("PNG: the " + name + " chunk at byte " + std::to_string(at) + " declares " + std::to_string(length) +
              " bytes");
    if (b.size() - at - 12 < length)
      Truncated("PNG: the " + name + " chunk at byte " + std::to_string(at) + " needs " + std::to_string(length) +
                " bytes, " + std::to_string(b.size() - at - 12) + " remain");
    if (name == "IEND") return chunks;
    data = data || name == "IDAT";
    if (name == "IDAT") chunks.idat += length;
    chunks.trns = chunks.trns || (name == "tRNS" && !data);
    at += 12 + size_t(length);
  }
}

TextureImageHeader ReadPngHeader(std::span<const unsigned char> b) {
  // IHDR must come first: 13 bytes of width, height, bit depth, colour type, compression,
  // filter and interlace method.
  if (b.size() < 33) Truncated("PNG: it ends at byte " + std::to_string(b.size()) + ", inside its IHDR chunk");
  if (Be32(b, 8) != 13 || ChunkName(b, 12) != "IHDR") Corrupt("PNG: its first chunk is not a 13-byte IHDR");
  TextureImageHeader header{Be32(b, 16), Be32(b, 20), 0, false, "PNG"};
  const uint32_t depth = b[24], colour = b[25];
  // The bit depths the PNG specification allows for each colour type.
  const bool valid = (colour == 0 && (depth == 1 || depth == 2 || depth == 4 || depth == 8 || depth == 16)) ||
                     (colour == 3 && (depth == 1 || depth == 2 || depth == 4 || depth == 8)) ||
                     ((colour == 2 || colour == 4 || colour == 6) && (depth == 8 || depth == 16));
  if (!valid) Corrupt("PNG: colour type " + std::to_string(colour) + " with " + std::to_string(depth) + "-bit samples");
  CheckSize(header.width, header.height);
  const PngChunks chunks = WalkPngChunks(b);
  // Deflate compresses at most 1032:1 (a 258-byte match in 2 bits), so image data too
  // short for the filtered rows the header declares is refused here, before stb allocates
  // the whole image: a decompression bomb's small file cannot claim 16384² pixels.
  const uint64_t samples = colour == 0 || colour == 3 ? 1 : colour == 4 ? 2 : colour == 2 ? 3 : 4;
  const uint64_t rows = uint64_t(header.height) * (1 + (uint64_t(header.width) * samples * depth + 7) / 8);
  if (chunks.idat * 1032 + 1032 < rows)
    Corrupt("PNG: " + std::to_string(chunks.idat) + " bytes of compressed image data cannot hold " +
            std::to_string(header.width) + " × " + std::to_string(header.height) + " pixels");
  header.channels = colour == 0 ? 1 : colour == 4 ? 2 : colour == 6 ? 4 : colour == 3 && chunks.trns ? 4 : 3;
  header.sixteenBit = depth == 16;
  return header;
}

// stb_image 2.27 (Debian 12's) does not bound the code count of a Huffman table: above
// 256 it writes past its tables, inside the decoder's state (UBSan found it). Every DHT
// segment is checked here before stb sees it.
void CheckHuffmanTables(std::span<const unsigned char> b, size_t at, size_t end) {
  while (at < end) {
    const std::string table = "JPEG: the Huffman table at byte " + std::to_string(at);
    if (end - at < 17) Corrupt(table + " is cut short");
    if (b[at] >> 4 > 1 || (b[at] & 15) > 3) Corrupt(table + " has an invalid class or number");
    size_t codes = 0;
    for (size_t i = 1; i <= 16; ++i) codes += b[at + i];
    if (codes > 256) Corrupt(table + " declares " + std::to_string(codes) + " codes; at most 256 exist");
    if (end - at - 17 < codes) Corrupt(table + " is cut short");
    at += 17 + codes;
  }
}

// Where the entropy-coded data that begins at `at` ends: at the 0xFF of the next marker
// (in the data a 0xFF byte is followed by 0, and restart markers belong to the data).
size_t SkipScanData(std::span<const unsigned char> b, size_t at) {
  for (; at + 1 < b.size(); ++at)
    if (b[at] == 0xff && b[at + 1] != 0 && !(b[at + 1] >= 0xd0 && b[at + 1] <= 0xd7)) return at;
  Truncated("JPEG: it ends inside its image data");
}

// The frame header (SOFn) segment whose length field is at `at`.
TextureImageHeader ReadJpegFrame(std::span<const unsigned char> b, unsigned marker, size_t at, size_t length) {
  char sof[8];
  std::snprintf(sof, sizeof sof, "FF %02X", marker);
  // stb decodes baseline, extended sequential and progressive Huffman JPEGs, 8-bit only.
  if (marker > 0xc2)
    throw Error("is a JPEG coded in a way stb_image cannot decode (frame marker " + std::string(sof) +
                ": lossless, hierarchical or arithmetic); only baseline and progressive JPEGs are supported");
  if (length < 8) Corrupt("JPEG: its frame header is " + std::to_string(length) + " bytes long");
  if (b[at + 2] != 8)
    throw Error("is a JPEG with " + std::to_string(b[at + 2]) + "-bit samples; only 8-bit JPEGs are supported");
  TextureImageHeader header{Be16(b, at + 5), Be16(b, at + 3), 0, false, "JPEG"};
  if (header.height == 0) throw Error("is a JPEG that gives its height only after the image data (DNL)");
  CheckSize(header.width, header.height);
  const unsigned components = b[at + 7];
  if (components != 1 && components != 3 && components != 4)
    throw Error("is a JPEG with " + std::to_string(components) + " colour components; 1, 3 or 4 are supported");
  header.channels = components == 1 ? 1 : 3;  // stb converts CMYK (4) to RGB
  return header;
}

// Each 8 × 8 block of a full-resolution component takes at least one bit of image data
// (its DC coefficient's Huffman code; a 1-bit code is the shortest, and a progressive AC
// scan's end-of-band run adds nothing), so image data too short for the blocks the frame
// declares is refused before stb allocates the image and fills it in from nothing.
void CheckScanBytes(const TextureImageHeader& header, uint64_t scanBytes) {
  const uint64_t blocks = uint64_t((header.width + 7) / 8) * ((header.height + 7) / 8);
  if (scanBytes * 8 < blocks)
    Corrupt("JPEG: " + std::to_string(scanBytes) + " bytes of image data cannot hold " + std::to_string(header.width) +
            " × " + std::to_string(header.height) + " pixels");
}

// Walks a JPEG's segments and scans from SOI to EOI: one frame header, before any scan;
// Huffman tables stb can hold; image data enough for the frame; nothing cut short.
TextureImageHeader ReadJpegHeader(std::span<const unsigned char> b) {
  std::optional<TextureImageHeader> header;
  uint64_t scanBytes = 0;
  for (size_t at = 2;;) {
    if (at >= b.size()) Truncated("JPEG: it ends at byte " + std::to_string(b.size()) + ", before its end marker");
    if (b[at] != 0xff) Corrupt("JPEG: no marker at byte " + std::to_string(at));
    while (at < b.size() && b[at] == 0xff) ++at;  // fill bytes may precede a marker
    if (at >= b.size()) Truncated("JPEG: it ends inside a marker");
    const unsigned marker = b[at++];
    if (marker == 0xd9) {
      if (!header) Corrupt("JPEG: it has no frame header");
      CheckScanBytes(*header, scanBytes);
      return *header;
    }
    if (marker == 0xd8 || marker == 0x01 || (marker >= 0xd0 && marker <= 0xd7)) continue;  // no length
    if (b.size() - at < 2) Truncated("JPEG: it ends inside a marker");
    const size_t length = Be16(b, at);
    if (length < 2) Corrupt("JPEG: a segment at byte " + std::to_string(at - 2) + " declares a length below 2");
    if (b.size() - at < length)
      Truncated("JPEG: the segment at byte " + std::to_string(at - 2) + " needs " + std::to_string(length) +
                " bytes, " + std::to_string(b.size() - at) + " remain");
    if (marker == 0xc4) CheckHuffmanTables(b, at + 2, at + length);
    if (marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc) {
      if (header) Corrupt("JPEG: a second frame header at byte " + std::to_string(at - 2));
      header = ReadJpegFrame(b, marker, at, length);
    }
    if (marker == 0xda && !header) Corrupt("JPEG: its image data comes before a frame header");
    if (marker == 0xda) {
      const size_t end = SkipScanData(b, at + length);
      scanBytes += end - (at + length);
      at = end;
    } else {
      at += length;
    }
  }
}

// stb's pixels, or what ended its decode: they must be the image the header declared.
template <typename T>
void CheckDecoded(const T* pixels, bool endOfData, const TextureImageHeader& header, int w, int h) {
  // stb asked for bytes past the end: whatever it had made of the rest is not the image.
  if (endOfData) Truncated(header.format + ": its data ends before the image does");
  // stb cannot tell a zlib stream or scan cut short inside complete chunks from a corrupt one.
  if (!pixels) {
    const char* reason = stbi_failure_reason();
    throw Error("is truncated or corrupt (" + header.format + ": " + (reason ? reason : "stb gives no reason") + ")");
  }
  if (uint32_t(w) != header.width || uint32_t(h) != header.height)
    throw Error("decodes to " + std::to_string(w) + " × " + std::to_string(h) + " pixels, but its header says " +
                std::to_string(header.width) + " × " + std::to_string(header.height));
}

}  // namespace

TextureImageHeader ReadTextureImageHeader(std::span<const unsigned char> bytes, std::string_view mimeType) {
  if (bytes.empty()) throw Error("is empty (0 bytes)");
  if (IsPng(bytes)) return ReadPngHeader(bytes);
  if (IsJpeg(bytes)) return ReadJpegHeader(bytes);
  if (IsWebp(bytes)) return ReadWebpHeader(bytes);
  std::string start;
  for (size_t i = 0; i < std::min<size_t>(bytes.size(), 4); ++i) {
    char hex[4];
    std::snprintf(hex, sizeof hex, i ? " %02X" : "%02X", bytes[i]);
    start += hex;
  }
  const std::string mime = mimeType.empty() ? "no mimeType" : "mimeType \"" + std::string(mimeType) + "\"";
  throw Error("is not PNG, JPEG or WebP (" + mime + ", first bytes " + start + ")");
}

Rgba8Image DecodeTextureImage(std::span<const unsigned char> bytes, const TextureImageHeader& header) {
  if (bytes.empty()) throw Error("is empty (0 bytes)");
  CheckSize(header.width, header.height);
  // The structure walk again (it costs little): a header read from other bytes must not
  // let a cut or malformed file through to stb.
  const TextureImageHeader actual = ReadTextureImageHeader(bytes, "");
  if (actual.format != header.format || actual.width != header.width || actual.height != header.height ||
      actual.sixteenBit != header.sixteenBit)
    throw Error("is a " + std::to_string(actual.width) + " × " + std::to_string(actual.height) + " " + actual.format +
                ", not the " + std::to_string(header.width) + " × " + std::to_string(header.height) + " " +
                header.format + " its header said");
  if (header.format == "WebP") return DecodeWebp(bytes, header);
  StbSource source{bytes};
  StbHeap heap;  // frees stb's pixels, and what it held when the reader ended its decode
  Rgba8Image image{header.width, header.height, {}};
  int w = 0, h = 0, channels = 0;
  bool endOfData = false;
  stbi__g_failure_reason = nullptr;  // so that a failure without a reason shows none, not an old one
  if (header.sixteenBit) {
    stbi_us* pixels = nullptr;
    try {
      pixels = stbi_load_16_from_callbacks(&kStbCallbacks, &source, &w, &h, &channels, 4);
    } catch (const StbEndOfData&) {
      endOfData = true;
    }
    CheckDecoded(pixels, endOfData, header, w, h);
    image.texels.resize(size_t(w) * size_t(h) * 4);
    for (size_t i = 0; i < image.texels.size(); ++i)
      image.texels[i] = uint8_t((uint32_t(pixels[i]) * 255 + 32767) / 65535);
  } else {
    stbi_uc* pixels = nullptr;
    try {
      pixels = stbi_load_from_callbacks(&kStbCallbacks, &source, &w, &h, &channels, 4);
    } catch (const StbEndOfData&) {
      endOfData = true;
    }
    CheckDecoded(pixels, endOfData, header, w, h);
    image.texels.assign(pixels, pixels + size_t(w) * size_t(h) * 4);
  }
  return image;
}

}  // namespace vkpt::internal

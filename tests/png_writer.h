// PNG files written by the tests themselves, byte by byte: stb_image_write has no palette
// or 16-bit PNGs, and a test of a decoder should control every chunk (a bomb's IHDR, a
// tRNS chunk, a cut). Deflate uses stored blocks only, which every inflater must accept.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vkpt::internal::test {

struct PngChunk {
  std::string type;  // four letters
  std::vector<uint8_t> data;
};

// CRC-32 as PNG chunks use it (ISO 3309, reflected, polynomial 0xEDB88320).
uint32_t PngCrc32(const std::vector<uint8_t>& bytes);

// The chunk as stored: length, type, data, CRC.
std::vector<unsigned char> PngChunkBytes(const PngChunk& chunk);

// Where the data of the first chunk of this type begins in `png`.
size_t PngChunkData(const std::vector<unsigned char>& png, const std::string& type);

// A PNG of `width` × `height` with the given bit depth and colour type (0 grey, 2 RGB,
// 3 palette, 4 grey+alpha, 6 RGBA). `samples` holds the rows top first, each packed as
// PNG stores it (16-bit samples big-endian, sub-byte samples left-aligned in a byte) and
// without the filter byte, which is added (0, none). It is cut into rows of the width's
// size whatever the size of the image, so a bomb can declare more than it holds.
// `beforeData` chunks (PLTE, tRNS) go between IHDR and IDAT.
std::vector<unsigned char> MakePng(uint32_t width, uint32_t height, int depth, int colour,
                                   const std::vector<uint8_t>& samples, const std::vector<PngChunk>& beforeData = {});

}  // namespace vkpt::internal::test

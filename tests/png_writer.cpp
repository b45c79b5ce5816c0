#include "png_writer.h"

#include <algorithm>
#include <stdexcept>

namespace vkpt::internal::test {
namespace {

void PutBe32(std::vector<uint8_t>& out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(uint8_t(v >> shift));
}

// zlib (RFC 1950) around deflate stored blocks (RFC 1951 §3.2.4): at most 65535 bytes a
// block, each LEN then its complement NLEN, little-endian; Adler-32 of the data last.
std::vector<uint8_t> ZlibStored(const std::vector<uint8_t>& data) {
  std::vector<uint8_t> out = {0x78, 0x01};
  size_t at = 0;
  do {
    const size_t n = std::min<size_t>(data.size() - at, 65535);
    const bool final = at + n == data.size();
    out.push_back(final ? 1 : 0);
    for (uint16_t v : {uint16_t(n), uint16_t(~n)}) {
      out.push_back(uint8_t(v));
      out.push_back(uint8_t(v >> 8));
    }
    out.insert(out.end(), data.begin() + at, data.begin() + at + n);
    at += n;
  } while (at < data.size());
  uint32_t a = 1, b = 0;
  for (uint8_t byte : data) {
    a = (a + byte) % 65521;
    b = (b + a) % 65521;
  }
  PutBe32(out, b << 16 | a);
  return out;
}

}  // namespace

uint32_t PngCrc32(const std::vector<uint8_t>& bytes) {
  uint32_t crc = 0xffffffffu;
  for (uint8_t byte : bytes) {
    crc ^= byte;
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1)));
  }
  return ~crc;
}

std::vector<unsigned char> PngChunkBytes(const PngChunk& chunk) {
  std::vector<uint8_t> out;
  out.reserve(12 + chunk.data.size());
  PutBe32(out, uint32_t(chunk.data.size()));
  for (char c : chunk.type) out.push_back(uint8_t(c));
  out.insert(out.end(), chunk.data.begin(), chunk.data.end());
  PutBe32(out, PngCrc32(std::vector<uint8_t>(out.begin() + 4, out.end())));  // of type and data
  return out;
}

size_t PngChunkData(const std::vector<unsigned char>& png, const std::string& type) {
  const auto at = std::search(png.begin(), png.end(), type.begin(), type.end());
  if (at == png.end()) throw std::invalid_argument("no " + type + " chunk");
  return size_t(at - png.begin()) + 4;
}

std::vector<unsigned char> MakePng(uint32_t width, uint32_t height, int depth, int colour,
                                   const std::vector<uint8_t>& samples, const std::vector<PngChunk>& beforeData) {
  const int channels = colour == 0 || colour == 3 ? 1 : colour == 2 ? 3 : colour == 4 ? 2 : 4;
  const size_t stride = (size_t(width) * channels * depth + 7) / 8;
  std::vector<uint8_t> rows;
  for (size_t at = 0; at < samples.size(); at += stride) {
    rows.push_back(0);  // filter: none
    rows.insert(rows.end(), samples.begin() + at, samples.begin() + std::min(samples.size(), at + stride));
  }
  std::vector<uint8_t> ihdr;
  PutBe32(ihdr, width);
  PutBe32(ihdr, height);
  ihdr.insert(ihdr.end(), {uint8_t(depth), uint8_t(colour), 0, 0, 0});
  std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<PngChunk> chunks = {{"IHDR", ihdr}};
  chunks.insert(chunks.end(), beforeData.begin(), beforeData.end());
  chunks.push_back({"IDAT", ZlibStored(rows)});
  chunks.push_back({"IEND", {}});
  for (const PngChunk& chunk : chunks) {
    const std::vector<unsigned char> bytes = PngChunkBytes(chunk);
    png.insert(png.end(), bytes.begin(), bytes.end());
  }
  return png;
}

}  // namespace vkpt::internal::test

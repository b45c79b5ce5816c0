#include "cluster/chunk_message.h"

#include <cstring>

#include "util/error.h"

namespace vkpt::internal {
namespace {

struct ChunkHeader {
  uint32_t chunk, width, height;
  uint32_t valueBytes;  // of each sum: 4 (float) or 8 (double)
  uint64_t rays, nonFinite, cutShort;
  double seconds;
};

// A pixel as sent: Σf and Σf² (six values) and its sample count.
size_t PixelBytes(uint32_t valueBytes) { return 6 * size_t(valueBytes) + sizeof(uint32_t); }

// Whether every sum is a float exactly (a GPU's are): then they go as floats, at half the
// bytes, and come back as the same doubles.
bool AllFloats(const FrameSums& sums) {
  for (const PixelSums& p : sums.pixels)
    for (int c = 0; c < 3; ++c)
      if (double(float(p.sum[c])) != p.sum[c] || double(float(p.sumOfSquares[c])) != p.sumOfSquares[c]) return false;
  return true;
}

template <typename T>
void PutPixels(const FrameSums& sums, uint8_t* at) {
  for (const PixelSums& p : sums.pixels) {
    const T v[6] = {T(p.sum.x), T(p.sum.y), T(p.sum.z), T(p.sumOfSquares.x), T(p.sumOfSquares.y), T(p.sumOfSquares.z)};
    std::memcpy(at, v, sizeof v);
    std::memcpy(at + sizeof v, &p.samples, sizeof p.samples);
    at += PixelBytes(sizeof(T));
  }
}

template <typename T>
void GetPixels(const uint8_t* at, FrameSums& sums) {
  for (PixelSums& p : sums.pixels) {
    T v[6];
    std::memcpy(v, at, sizeof v);
    std::memcpy(&p.samples, at + sizeof v, sizeof p.samples);
    p.sum = {v[0], v[1], v[2]};
    p.sumOfSquares = {v[3], v[4], v[5]};
    at += PixelBytes(sizeof(T));
  }
}

}  // namespace

std::vector<uint8_t> EncodeChunk(uint32_t chunk, const FrameSums& sums, double seconds) {
  const uint32_t valueBytes = AllFloats(sums) ? sizeof(float) : sizeof(double);
  const ChunkHeader h{chunk, sums.width, sums.height, valueBytes, sums.rays, sums.nonFinite, sums.cutShort, seconds};
  std::vector<uint8_t> bytes(sizeof h + sums.pixels.size() * PixelBytes(valueBytes));
  std::memcpy(bytes.data(), &h, sizeof h);
  if (valueBytes == sizeof(float)) PutPixels<float>(sums, bytes.data() + sizeof h);
  else PutPixels<double>(sums, bytes.data() + sizeof h);
  return bytes;
}

FrameSums DecodeChunk(const std::vector<uint8_t>& bytes, uint32_t* chunk, double* seconds) {
  ChunkHeader h;
  if (bytes.size() < sizeof h) throw Error("MPI: a chunk's message is truncated");
  std::memcpy(&h, bytes.data(), sizeof h);
  const uint64_t pixels = uint64_t(h.width) * h.height;
  if ((h.valueBytes != sizeof(float) && h.valueBytes != sizeof(double)) ||
      bytes.size() != sizeof h + pixels * PixelBytes(h.valueBytes))
    throw Error("MPI: a chunk's message has the wrong size");
  FrameSums s;
  s.width = h.width;
  s.height = h.height;
  s.rays = h.rays;
  s.nonFinite = h.nonFinite;
  s.cutShort = h.cutShort;
  s.pixels.resize(pixels);
  if (h.valueBytes == sizeof(float)) GetPixels<float>(bytes.data() + sizeof h, s);
  else GetPixels<double>(bytes.data() + sizeof h, s);
  *chunk = h.chunk;
  *seconds = h.seconds;
  return s;
}

}  // namespace vkpt::internal

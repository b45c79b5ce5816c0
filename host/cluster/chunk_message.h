// A chunk's sums as one rank sends them to rank 0 (cluster/chunk_dealer.h): a header
// with the chunk's index, size, counters and render time, then every pixel's sums.
#pragma once

#include <cstdint>
#include <vector>

#include "render/film.h"

namespace vkpt::internal {

// A chunk's sums as sent, with the seconds it took to render, and back: a 48-byte header
// and 28 bytes per pixel when every sum is a float exactly (a GPU's chunk), else 52.
std::vector<uint8_t> EncodeChunk(uint32_t chunk, const FrameSums& sums, double seconds);
FrameSums DecodeChunk(const std::vector<uint8_t>& bytes, uint32_t* chunk, double* seconds);

}  // namespace vkpt::internal

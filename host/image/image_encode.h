// Image → the bytes of an image file, built in memory so that all file I/O goes through
// one checked writer (util/atomic_write.h). Allocation failure throws std::bad_alloc.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace vkpt {

// 8-bit sRGB, pixels scaled by 2^exposure before the transfer curve.
std::vector<uint8_t> EncodePng(const Image& image, float exposure);

// Linear 32-bit float, little-endian, rows bottom to top as PFM stores them.
std::vector<uint8_t> EncodePfm(const Image& image);

// Linear 32-bit float, ZIP-compressed (lossless). Throws vkpt::Error naming `path` if
// tinyexr refuses the image.
std::vector<uint8_t> EncodeExr(const Image& image, const std::string& path);

}  // namespace vkpt

// Image → the bytes of an image file, built in memory so that all file I/O goes through
// one checked writer (util/atomic_write.h). Allocation failure throws std::bad_alloc.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"
#include "image/view_transform.h"

namespace vkpt::internal {

// 8-bit sRGB of the pixels as `display` shows them.
std::vector<uint8_t> EncodePng(const Image& image, const DisplayTransform& display);

// 8-bit RGB bytes (row-major from the top row, three per pixel) as they are.
std::vector<uint8_t> EncodePngRgb8(uint32_t width, uint32_t height, const std::vector<uint8_t>& rgb);

// Linear 32-bit float, little-endian, rows bottom to top as PFM stores them.
std::vector<uint8_t> EncodePfm(const Image& image);

// Linear 32-bit float, ZIP-compressed (lossless). Throws Error naming `path` if
// tinyexr refuses the image.
std::vector<uint8_t> EncodeExr(const Image& image, const std::string& path);

// One channel of an EXR image: its name ("R", "albedo.G", "depth.Z") and width × height
// values, row-major from the top row.
struct ExrChannel {
  std::string name;
  std::vector<float> values;
};

// The image's R, G and B channels.
std::vector<ExrChannel> RgbChannels(const Image& image);

// Any channels as 32-bit float, ZIP-compressed, listed in name order as the format wants.
// Throws Error naming `path` if a channel is malformed or tinyexr refuses.
std::vector<uint8_t> EncodeExrChannels(uint32_t width, uint32_t height, std::vector<ExrChannel> channels,
                                       const std::string& path);

}  // namespace vkpt::internal

#include "image/webp_decode.h"

#include <webp/decode.h>

#include <algorithm>
#include <string>

#include "util/error.h"

namespace vkpt::internal {
namespace {

uint32_t Le32(std::span<const unsigned char> b, size_t at) {
  return uint32_t(b[at]) | uint32_t(b[at + 1]) << 8 | uint32_t(b[at + 2]) << 16 | uint32_t(b[at + 3]) << 24;
}

}  // namespace

bool IsWebp(std::span<const unsigned char> b) {
  return b.size() >= 12 && std::equal(b.begin(), b.begin() + 4, "RIFF") &&
         std::equal(b.begin() + 8, b.begin() + 12, "WEBP");
}

TextureImageHeader ReadWebpHeader(std::span<const unsigned char> b) {
  // libwebp decodes what the bytes hold of a file cut short; the RIFF size tells.
  const uint64_t riff = uint64_t(Le32(b, 4)) + 8;
  if (riff > b.size())
    throw Error("is truncated (WebP: its RIFF header declares " + std::to_string(riff) + " bytes, " +
                std::to_string(b.size()) + " are there)");
  WebPBitstreamFeatures features;
  const VP8StatusCode status = WebPGetFeatures(b.data(), size_t(riff), &features);
  if (status != VP8_STATUS_OK)
    throw Error("is truncated or corrupt (WebP: its header does not parse, libwebp status " + std::to_string(status) +
                ")");
  if (features.has_animation) throw Error("is an animated WebP; a texture must be a still image");
  if (features.width < 1 || features.height < 1 || uint32_t(features.width) > kMaxTextureSide ||
      uint32_t(features.height) > kMaxTextureSide)
    throw Error("is " + std::to_string(features.width) + " × " + std::to_string(features.height) +
                " pixels; a texture's sides must be 1 to " + std::to_string(kMaxTextureSide));
  return {uint32_t(features.width), uint32_t(features.height), features.has_alpha ? 4u : 3u, false, "WebP"};
}

Rgba8Image DecodeWebp(std::span<const unsigned char> bytes, const TextureImageHeader& header) {
  Rgba8Image image{header.width, header.height, std::vector<uint8_t>(size_t(header.width) * header.height * 4)};
  const size_t riff = size_t(Le32(bytes, 4)) + 8;
  const int stride = int(header.width * 4);
  if (!WebPDecodeRGBAInto(bytes.data(), riff, image.texels.data(), image.texels.size(), stride))
    throw Error("is truncated or corrupt (WebP: libwebp could not decode its " + std::to_string(header.width) + " × " +
                std::to_string(header.height) + " image)");
  return image;
}

}  // namespace vkpt::internal

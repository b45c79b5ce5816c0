// WebP texture images (EXT_texture_webp) through libwebp: the RIFF container and the
// bitstream's header checked before anything is decoded, still images only.
#pragma once

#include <span>

#include "image/texture_decode.h"

namespace vkpt::internal {

// Whether the bytes start as a WebP file does ("RIFF", a size, "WEBP").
bool IsWebp(std::span<const unsigned char> bytes);

// The image's size and channels from its headers; a RIFF size past the bytes there are
// (a file cut short), an animation or a malformed header is a Error.
TextureImageHeader ReadWebpHeader(std::span<const unsigned char> bytes);

// The texels (RGBA8, top row first) of an image ReadWebpHeader accepted; a bitstream
// that does not decode to that image is a Error.
Rgba8Image DecodeWebp(std::span<const unsigned char> bytes, const TextureImageHeader& header);

}  // namespace vkpt::internal

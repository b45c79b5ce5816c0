// Reading environment maps: Radiance RGBE .hdr (stb_image) and OpenEXR .exr (tinyexr)
// files as linear RGB float images. Both are untrusted input (docs/security.md): only a
// regular file is opened, its size and the image's dimensions are checked from its header
// before anything is decoded, and memory is charged before it is allocated.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "image/image.h"

namespace vkpt::internal {

// Called with the bytes about to be allocated and what for ("the file"); throws to refuse.
using MemoryCharge = std::function<void(uint64_t bytes, const std::string& what)>;

// The largest width or height accepted (lavapipe's maxImageDimension2D).
constexpr uint32_t kMaxEnvironmentSide = 16384;

// The map in `path` (.hdr or .exr, by extension) with row 0 at the top. Every texel is
// finite: a NaN or infinity is an error naming the texel. Negative components, which
// EXR filters and converters leave behind but which no radiance can be, are set to 0 and
// counted in a warning appended to `warnings`. Errors are Error naming the file.
Image ReadEnvironmentImage(const std::string& path, const MemoryCharge& charge, std::vector<std::string>* warnings);

}  // namespace vkpt::internal

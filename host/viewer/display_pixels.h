// A render as a window shows it: each pixel through the view transform and the sRGB
// curve as a PNG's (image/image_encode.cpp), so the window's picture is the PNG's; an
// AOV mapped to colours a person can read.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/view_transform.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal {

// 8-bit RGBA (alpha 255), row-major from the top row, of `image`'s RGB radiance.
std::vector<uint8_t> DisplayPixels(const vkpt::Image& image, const DisplayTransform& display);

// An AOV (docs/aovs.md) as a picture: albedo as its colour, a normal's components mapped
// from [−1, 1] to [0, 1], depth nearer brighter (1 − z / the farthest; no hit black), ids
// each in a colour of its own (none black).
std::vector<uint8_t> DisplayAov(const vkpt::Image& aov, const std::string& name);

}  // namespace vkpt::internal

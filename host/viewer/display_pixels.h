// A render as a window shows it: each pixel through the view transform and the sRGB
// curve as a PNG's (image/image_encode.cpp), so the window's picture is the PNG's.
#pragma once

#include <cstdint>
#include <vector>

#include "image/view_transform.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal {

// 8-bit RGBA (alpha 255), row-major from the top row, of `image`'s RGB radiance.
std::vector<uint8_t> DisplayPixels(const vkpt::Image& image, const DisplayTransform& display);

}  // namespace vkpt::internal

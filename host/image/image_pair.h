// What every comparison of two images pixel by pixel (image_compare.h) checks first, and
// which channels it can use: shared by CompareImages, DifferenceHeatmap and RelativeMse.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>

#include "image/image.h"
#include "util/error.h"

namespace vkpt::internal {

inline bool HasVariance(const Image& img) { return !img.variance.empty(); }

// A channel is usable when its value (and variance, if the image has them) is finite.
inline bool FiniteChannel(const Image& img, size_t i, int c) {
  return std::isfinite(img.pixels[i][c]) && (!HasVariance(img) || std::isfinite(img.variance[i][c]));
}

// Throws Error unless `img` (named `name` in the message) has width × height pixels
// and, if it has variances, as many of them.
inline void ValidatePixelCounts(const Image& img, const char* name) {
  size_t n = size_t(img.width) * img.height;
  if (img.pixels.size() != n)
    throw Error(std::string("image ") + name + ": " + std::to_string(img.pixels.size()) + " pixels for a " +
                std::to_string(img.width) + "×" + std::to_string(img.height) + " image");
  if (HasVariance(img) && img.variance.size() != n)
    throw Error(std::string("image ") + name + ": " + std::to_string(img.variance.size()) + " variances for " +
                std::to_string(n) + " pixels");
}

// Throws Error unless both images are well-formed and of the same size.
inline void CheckSameSize(const Image& a, const Image& b) {
  ValidatePixelCounts(a, "A");
  ValidatePixelCounts(b, "B");
  if (a.width != b.width || a.height != b.height)
    throw Error("cannot compare images of different sizes: " + std::to_string(a.width) + "×" +
                std::to_string(a.height) + " and " + std::to_string(b.width) + "×" + std::to_string(b.height));
}

}  // namespace vkpt::internal

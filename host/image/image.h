// A linear RGB float image with optional per-pixel variance of the mean, and writers for
// .png (8-bit sRGB), .pfm (linear float) and .exr (linear float).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "image/view_transform.h"

namespace vkpt::internal {

struct Image {
  uint32_t width = 0, height = 0;
  std::vector<glm::vec3> pixels;    // mean radiance, row 0 at the top
  std::vector<glm::vec3> variance;  // variance of the mean per pixel (may be empty)

  Image() = default;
  Image(uint32_t w, uint32_t h) : width(w), height(h), pixels(size_t(w) * h, glm::vec3(0.0f)) {}
  glm::vec3& At(uint32_t x, uint32_t y) { return pixels[size_t(y) * width + x]; }
  const glm::vec3& At(uint32_t x, uint32_t y) const { return pixels[size_t(y) * width + x]; }
};

enum class ImageFormat { Png, Pfm, Exr };

// Format from the file extension (case-insensitive); throws Error for others.
ImageFormat FormatFromPath(const std::string& path);

// Checks, before a long render, that `path` has a known image extension and that its
// directory exists and is writable; throws Error naming the path otherwise.
void CheckOutputPath(const std::string& path);

// Encodes in memory, then writes atomically (util/atomic_write.h): every write checked,
// fsynced, renamed over `path` only when complete. On failure Error names `path`
// and the OS error, and neither a partial file nor a temporary is left behind.
// `display` applies to PNG only; float formats stay linear and unscaled.
void WriteImage(const Image& image, const std::string& path, const DisplayTransform& display = {});

// Reads a .pfm written by WriteImage (or any 3-channel little/big-endian PFM).
Image ReadPfm(const std::string& path);

// Linear → 8-bit sRGB (IEC 61966-2-1 transfer curve), clamped to [0, 1].
uint8_t LinearToSrgb8(float linear);

}  // namespace vkpt::internal

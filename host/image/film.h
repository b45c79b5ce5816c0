// The film, and what a render returns. Both renderers add up each pixel's samples (Σf and
// Σf², channel by channel) their own way — the CPU in double per pixel, the GPU in float
// storage buffers — and hand the sums to a Film, the one place that turns them into the
// image: the pixel's mean and the variance of that mean. As in pbrt-v4's RGBFilm
// (Pharr, Jakob and Humphreys, "Physically Based Rendering", 4th ed., 5.4), the film keeps
// the estimator's bookkeeping out of the integrators.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>

#include <glm/glm.hpp>

#include "image/image.h"

namespace vkpt {

// Sums over one pixel's samples of the radiance f and of f².
struct PixelSums {
  glm::dvec3 sum{0.0};
  glm::dvec3 sumOfSquares{0.0};
};

class Film {
 public:
  // Every pixel's sums are over `samplesPerPixel` samples. A sample a renderer discards
  // (non-finite) still counts in n: it adds 0 to both sums.
  Film(uint32_t width, uint32_t height, uint32_t samplesPerPixel) : image_(width, height), n_(samplesPerPixel) {
    image_.variance.assign(image_.pixels.size(), glm::vec3(0.0f));
  }

  // Pixel i (row-major) from its sums: the mean Σf/n, and the variance of that mean,
  // s²/n with s² = (Σf² − n·mean²)/(n − 1) the unbiased sample variance (0 for n = 1).
  // Distinct pixels may be set from different threads at once.
  void SetPixel(size_t i, const PixelSums& s) {
    const glm::dvec3 mean = s.sum / n_;
    image_.pixels[i] = glm::vec3(mean);
    if (n_ > 1) image_.variance[i] = glm::vec3(glm::max(s.sumOfSquares / n_ - mean * mean, 0.0) / (n_ - 1.0));
  }

  Image TakeImage() { return std::move(image_); }

 private:
  Image image_;
  double n_;
};

// What either renderer returns.
struct RenderResult {
  Image image;             // from a Film: mean and variance of the mean per pixel
  uint64_t rays = 0;       // closest-hit and shadow rays traced
  uint64_t nonFinite = 0;  // samples discarded because they were NaN or Inf (a bug if > 0)
  // Vulkan: samples whose SIMD group came near lavapipe's 65535-loop-iteration limit, so
  // they may have been ended early (biased dark). 0 for any sane scene; reported if not.
  uint64_t cutShort = 0;
  double seconds = 0.0;               // rendering alone (Vulkan: dispatches and readback)
  std::string engine;                 // for reports: "cpu (2 threads)", "vulkan: <device> (up to …)"
  unsigned threads = 0;               // CPU: threads used
  uint32_t batches = 0;               // Vulkan: submissions
  uint32_t samplesPerInvocation = 0;  // Vulkan: the longest run of samples per invocation
};

}  // namespace vkpt

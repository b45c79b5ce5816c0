#include "session/noise_estimate.h"

#include <algorithm>
#include <limits>

namespace vkpt::internal {

double PixelRelativeError(const PixelSums& s) {
  if (s.samples < 2) return std::numeric_limits<double>::infinity();
  const double n = s.samples;
  const glm::dvec3 mean = s.sum / n;
  const glm::dvec3 varianceOfMean = glm::max(s.sumOfSquares / n - mean * mean, 0.0) / (n - 1.0);
  const glm::dvec3 rel = varianceOfMean / (mean * mean + 0.01);
  return (rel.x + rel.y + rel.z) / 3.0;
}

double EstimatedRelMse(const FrameSums& sums) {
  if (sums.pixels.empty()) return 0.0;
  double total = 0.0;
  for (const PixelSums& p : sums.pixels) total += PixelRelativeError(p);
  return total / double(sums.pixels.size());
}

uint64_t UpdateActivePixels(const FrameSums& sums, double target, std::vector<uint8_t>& active) {
  const uint32_t w = sums.width, h = sums.height;
  const size_t n = size_t(w) * h;
  if (active.size() != n) active.assign(n, 1);
  std::vector<uint8_t> noisy(n);
  for (size_t i = 0; i < n; ++i) noisy[i] = active[i] && PixelRelativeError(sums.pixels[i]) > target;
  uint64_t count = 0;
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      if (!active[i]) continue;
      bool keep = false;
      for (uint32_t yy = y > 0 ? y - 1 : 0; yy <= std::min(y + 1, h - 1) && !keep; ++yy)
        for (uint32_t xx = x > 0 ? x - 1 : 0; xx <= std::min(x + 1, w - 1) && !keep; ++xx)
          keep = noisy[size_t(yy) * w + xx] != 0;
      active[i] = keep;
      count += keep;
    }
  return count;
}

}  // namespace vkpt::internal

// The per-pixel measures of how two images differ: DifferenceHeatmap and RelativeMse.
#include "image/image_compare.h"

#include <algorithm>
#include <cmath>

#include "image/image_pair.h"

namespace vkpt::internal {
namespace {

// sRGB display value → linear, so the heat map's ramp is even on screen after
// WriteImage's LinearToSrgb8.
float SrgbToLinear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

// t ∈ [0, 1]: black → yellow (0.5) → red (1), in display space.
glm::vec3 HeatColour(double t) {
  t = std::clamp(t, 0.0, 1.0);
  float r = float(std::min(1.0, 2.0 * t)), g = float(t <= 0.5 ? 2.0 * t : 2.0 - 2.0 * t);
  return glm::vec3(SrgbToLinear(r), SrgbToLinear(g), 0.0f);
}

}  // namespace

Image DifferenceHeatmap(const Image& a, const Image& b) {
  CheckSameSize(a, b);
  const bool useVariance = HasVariance(a) && HasVariance(b);
  Image out{a.width, a.height};
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    double score = 0.0;  // in [0, 1], the largest over the channels
    bool finite = true;
    for (int c = 0; c < 3; ++c) {
      if (!FiniteChannel(a, i, c) || !FiniteChannel(b, i, c)) {
        finite = false;
        break;
      }
      double va = a.pixels[i][c], vb = b.pixels[i][c], d = std::abs(va - vb);
      if (d == 0.0) continue;
      double t;
      if (useVariance) {
        double sd = std::sqrt(double(a.variance[i][c]) + double(b.variance[i][c]));
        t = sd > 0.0 ? d / sd / 6.0 : 1.0;  // z / 6: z = 3 is yellow, z ≥ 6 red
      } else {
        double rel = d / std::max({std::abs(va), std::abs(vb), 1e-6});
        t = (std::log10(rel) + 6.0) / 6.0;  // 1e-6 black, 1e-3 yellow, 1 red
      }
      score = std::max(score, t);
    }
    out.pixels[i] = finite ? HeatColour(score) : glm::vec3(1.0f, 0.0f, 1.0f);
  }
  return out;
}

double RelativeMse(const Image& a, const Image& reference) {
  CheckSameSize(a, reference);
  double total = 0.0;
  for (size_t i = 0; i < reference.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double d = double(a.pixels[i][c]) - reference.pixels[i][c], r = reference.pixels[i][c];
      total += d * d / (r * r + 0.01);
    }
  return total / (3.0 * reference.pixels.size());
}

}  // namespace vkpt::internal

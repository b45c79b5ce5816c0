#include "render/environment_map.h"

#include <chrono>
#include <cmath>

#include "shared/sampling.h"
#include "util/parallel.h"

namespace vkpt::internal {
namespace {

// CDF entries [first, first + n) as inclusive running sums of weight[0..n) / total, the
// last exactly 1 so that every u < 1 finds an interval; all-zero weights give the uniform
// CDF (as pbrt-v4's PiecewiseConstant1D), whose cells the other axis never picks.
template <class Weight>
double WriteCdf(float* cdf, uint32_t n, Weight weight) {
  double total = 0.0;
  for (uint32_t k = 0; k < n; ++k) total += weight(k);
  double running = 0.0;
  for (uint32_t k = 0; k < n; ++k) {
    running += total > 0.0 ? weight(k) : 1.0;
    cdf[k] = k + 1 == n ? 1.0f : float(running / (total > 0.0 ? total : double(n)));
  }
  return total;
}

}  // namespace

EnvironmentMap BuildEnvironmentMap(uint32_t width, uint32_t height, std::span<const glm::vec3> radiance,
                                   unsigned threads) {
  const auto start = std::chrono::steady_clock::now();
  EnvironmentMap env;
  env.width = width;
  env.height = height;
  const size_t texels = size_t(width) * height;
  env.texels.resize(texels);
  std::vector<float> luminance(texels);
  for (size_t i = 0; i < texels; ++i) {
    env.texels[i] = glm::vec4(radiance[i], 0.0f);
    luminance[i] = shader::Luminance(radiance[i]);
  }
  // A cell's weight is the integral of what EnvRadiance returns over it: the bilinear
  // reconstruction integrates to the texels of its 3 × 3 neighbourhood weighted by the
  // tent (1, 6, 1)/8 in each axis (wrapping in u, clamped in v as the lookup is). So every
  // direction with non-zero radiance has a non-zero pdf, which a texel's own value would
  // not give next to a bright texel (pbrt-v3 filters its lookups for the same reason,
  // §14.2.4), and none gets more than its share. Times sin θ at the row's centre: the
  // cell's solid angle (pbrt-v3 §13.6.7).
  env.cdf.resize(texels + height);
  std::vector<double> rowWeight(height);
  ParallelFor(
      height, ThreadCount(threads),
      [&](size_t j) {
        const float* above = &luminance[(j > 0 ? j - 1 : 0) * width];
        const float* row = &luminance[j * width];
        const float* below = &luminance[std::min<size_t>(j + 1, height - 1) * width];
        const double sinTheta = std::sin(M_PI * (double(j) + 0.5) / height);
        auto vertical = [&](uint32_t i) { return (double(above[i]) + 6.0 * row[i] + below[i]) / 8.0; };
        rowWeight[j] = WriteCdf(&env.cdf[j * width], width, [&](uint32_t i) {
          uint32_t left = i > 0 ? i - 1 : width - 1, right = i + 1 < width ? i + 1 : 0;
          return sinTheta * (vertical(left) + 6.0 * vertical(i) + vertical(right)) / 8.0;
        });
      },
      16);
  WriteCdf(&env.cdf[texels], height, [&](uint32_t j) { return rowWeight[j]; });
  env.buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return env;
}

void SetEnvironmentParams(shader::FrameParams& params, const EnvironmentMap& env, float rotationDegrees,
                          float intensity) {
  params.envWidth = env.width;
  params.envHeight = env.height;
  params.envIntensity = intensity;
  const double alpha = double(rotationDegrees) * M_PI / 180.0;
  params.envRotationCos = float(std::cos(alpha));
  params.envRotationSin = float(std::sin(alpha));
}

}  // namespace vkpt::internal

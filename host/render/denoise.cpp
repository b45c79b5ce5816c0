#include "render/denoise.h"

#include <utility>

#include "render/film.h"
#include "util/error.h"
#include "util/parallel.h"

namespace vkpt::internal {

// The scene access of shared/denoise.h: the arrays of one iteration.
struct DenoiseView {
  const glm::vec4* color;
  const glm::vec4* guide;
  const glm::vec4* albedo;
};

}  // namespace vkpt::internal

#define VKPT_DENOISE_PARAM const ::vkpt::internal::DenoiseView &view,
#define VKPT_DENOISE_ARG view,
#define VKPT_DENOISE_COLOR(i) view.color[i]
#define VKPT_DENOISE_GUIDE(i) view.guide[i]
#define VKPT_DENOISE_ALBEDO(i) vec3(view.albedo[i])
#include "shared/denoise.h"

namespace vkpt::internal {

DenoiseInput PrepareDenoise(const Image& image, const AovSums& aovs) {
  const size_t n = image.pixels.size();
  if (image.variance.size() != n || aovs.pixels.size() != n || aovs.samples == 0)
    throw Error("the denoiser needs the image's variance and the AOV pass of the same frame");
  DenoiseInput in;
  in.width = image.width;
  in.height = image.height;
  in.color.resize(n);
  in.guide.resize(n);
  in.albedo.resize(n);
  const glm::vec3 luminance(0.2126f, 0.7152f, 0.0722f);
  for (size_t i = 0; i < n; ++i) {
    const AovPixel a = ResolveAovPixel(aovs.pixels[i], aovs.samples);
    const glm::vec3 albedo = glm::max(a.albedo, glm::vec3(kMinAlbedo));
    const glm::vec3 c = image.pixels[i] / albedo;
    const glm::vec3 v = image.variance[i] / (albedo * albedo);
    in.color[i] = glm::vec4(c, glm::dot(luminance * luminance, v));
    in.guide[i] = glm::vec4(a.normal, a.depth);
    in.albedo[i] = glm::vec4(albedo, 0.0f);
  }
  return in;
}

std::optional<std::vector<glm::vec4>> AtrousCpu(const DenoiseInput& input, unsigned threads, const StopFilter& stop) {
  std::vector<glm::vec4> from = input.color, to(from.size());
  for (uint32_t it = 0; it < shader::kDenoiseIterations; ++it) {
    if (stop && stop()) return std::nullopt;
    const DenoiseView view{from.data(), input.guide.data(), input.albedo.data()};
    ParallelFor(input.height, ThreadCount(threads), [&](size_t y) {
      for (uint32_t x = 0; x < input.width; ++x)
        to[y * input.width + x] = shader::AtrousPixel(view, input.width, input.height, x, uint32_t(y), it);
    });
    std::swap(from, to);
  }
  return from;
}

Image FinishDenoise(const DenoiseInput& input, const std::vector<glm::vec4>& filtered) {
  Image out(input.width, input.height);
  out.variance.resize(out.pixels.size());
  for (size_t i = 0; i < out.pixels.size(); ++i) {
    const glm::vec3 albedo(input.albedo[i]);
    out.pixels[i] = glm::vec3(filtered[i]) * albedo;
    // The filtered luminance variance, spread over the channels as the albedo scales them.
    out.variance[i] = glm::vec3(filtered[i].w) * albedo * albedo;
  }
  return out;
}

}  // namespace vkpt::internal

#include "render/film.h"

namespace vkpt {

Image ResolveFilm(const FrameSums& sums) {
  Film film(sums.width, sums.height);
  for (size_t i = 0; i < sums.pixels.size(); ++i) film.SetPixel(i, sums.pixels[i]);
  return film.TakeImage();
}

uint64_t TotalSamples(const FrameSums& sums) {
  uint64_t n = 0;
  for (const PixelSums& p : sums.pixels) n += p.samples;
  return n;
}

AovPixel ResolveAovPixel(const AovPixelSums& a, uint32_t samples) {
  const double perSample = samples > 0 ? 1.0 / samples : 0.0;
  const double perHit = a.hits > 0 ? 1.0 / a.hits : 0.0;
  return {glm::vec3(a.albedo * perSample), glm::vec3(a.normal * perSample), glm::vec3(a.position * perHit),
          float(a.depth * perHit), float(a.boxTests * perSample)};
}

}  // namespace vkpt

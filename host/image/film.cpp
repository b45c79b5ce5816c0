#include "image/film.h"

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

}  // namespace vkpt

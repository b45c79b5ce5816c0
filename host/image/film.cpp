#include "image/film.h"

namespace vkpt {

Image ResolveFilm(const FrameSums& sums) {
  Film film(sums.width, sums.height);
  for (size_t i = 0; i < sums.pixels.size(); ++i) film.SetPixel(i, sums.pixels[i]);
  return film.TakeImage();
}

}  // namespace vkpt

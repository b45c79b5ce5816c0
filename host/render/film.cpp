#include "render/film.h"

#include "util/error.h"

namespace vkpt::internal {

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

void SizeToAdd(FrameSums& frame, uint32_t width, uint32_t height) {
  if (frame.pixels.empty()) {
    frame.width = width;
    frame.height = height;
    frame.pixels.resize(size_t(width) * height);
  }
  if (frame.width != width || frame.height != height) throw Error("a chunk's size differs from its frame's");
}

void AddChunk(FrameSums& frame, const FrameSums& chunk) {
  SizeToAdd(frame, chunk.width, chunk.height);
  for (size_t i = 0; i < frame.pixels.size(); ++i) {
    frame.pixels[i].sum += chunk.pixels[i].sum;
    frame.pixels[i].sumOfSquares += chunk.pixels[i].sumOfSquares;
    frame.pixels[i].samples += chunk.pixels[i].samples;
  }
  frame.rays += chunk.rays;
  frame.nonFinite += chunk.nonFinite;
  frame.cutShort += chunk.cutShort;
}

}  // namespace vkpt::internal

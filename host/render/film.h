// The film, a render in progress, and what a render returns. Both renderers add up each
// pixel's samples (Σf and Σf², channel by channel, and their count) their own way — the
// CPU in double per pixel, the GPU in float storage buffers — and hand the sums to a Film,
// the one place that turns them into the image: the pixel's mean and the variance of that
// mean. As in pbrt-v4's RGBFilm (Pharr, Jakob and Humphreys, "Physically Based
// Rendering", 4th ed., 5.4), the film keeps the estimator's bookkeeping out of the
// integrators.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"

namespace vkpt::internal {

// Sums over one pixel's samples of the radiance f and of f², and how many samples they
// hold. A sample a renderer discards (non-finite) still counts: it adds 0 to both sums.
struct PixelSums {
  glm::dvec3 sum{0.0};
  glm::dvec3 sumOfSquares{0.0};
  uint32_t samples = 0;
};

class Film {
 public:
  Film(uint32_t width, uint32_t height) : image_(width, height) {
    image_.variance.assign(image_.pixels.size(), glm::vec3(0.0f));
  }

  // Pixel i (row-major) from its sums: the mean Σf/n, and the variance of that mean,
  // s²/n with s² = (Σf² − n·mean²)/(n − 1) the unbiased sample variance (0 for n ≤ 1; a
  // pixel without samples is black). Distinct pixels may be set from different threads.
  void SetPixel(size_t i, const PixelSums& s) {
    if (s.samples == 0) return;
    const double n = s.samples;
    const glm::dvec3 mean = s.sum / n;
    image_.pixels[i] = glm::vec3(mean);
    if (n > 1) image_.variance[i] = glm::vec3(glm::max(s.sumOfSquares / n - mean * mean, 0.0) / (n - 1.0));
  }

  Image TakeImage() { return std::move(image_); }

 private:
  Image image_;
};

// The running sums of a render and the renderer's counters.
struct FrameSums {
  uint32_t width = 0, height = 0;
  std::vector<PixelSums> pixels;  // row-major
  uint64_t rays = 0;              // closest-hit and shadow rays traced
  uint64_t nonFinite = 0;         // samples discarded because they were NaN or Inf (a bug if > 0)
  // Vulkan: samples whose SIMD group came near lavapipe's 65535-loop-iteration limit, so
  // they may have been ended early (biased dark). 0 for any sane scene; reported if not.
  uint64_t cutShort = 0;
};

// Adds a chunk's sums to the frame's: every pixel's Σf, Σf² and count, and the counters
// (an empty frame takes the chunk's size). Chunks must be added in chunk order for the
// result to be the one every render makes (session/chunked_frame.h).
void AddChunk(FrameSums& frame, const FrameSums& chunk);

// Before sums of a width × height frame are added to `frame`: an empty one takes that
// size (zero sums); one of another size is an error.
void SizeToAdd(FrameSums& frame, uint32_t width, uint32_t height);

// The image of the sums: every pixel through a Film.
Image ResolveFilm(const FrameSums& sums);

// Every pixel's samples added up.
uint64_t TotalSamples(const FrameSums& sums);

// Sums over one pixel's AOV samples (shaders/shared/aov.h), in double like PixelSums:
// albedo, normal and box tests over all samples, depth and position over those that hit.
struct AovPixelSums {
  glm::dvec3 albedo{0.0};
  glm::dvec3 normal{0.0};
  glm::dvec3 position{0.0};
  double depth = 0.0;
  double boxTests = 0.0;
  uint32_t hits = 0;
  uint32_t triangle = 0xFFFFFFFFu;  // the scene triangle at the pixel's centre (shared/aov.h); none: kInvalidIndex
};

// What an AOV pass renders: the first `samples` samples of every pixel, and with `ids` the
// scene triangle at each pixel's centre (the id AOVs; else AovPixelSums::triangle stays
// kInvalidIndex and no ray is traced for it).
struct AovRequest {
  uint32_t samples = 0;
  bool ids = false;
};

// The AOV sums of a frame: samples [0, samples) of every pixel.
struct AovSums {
  uint32_t width = 0, height = 0;
  uint32_t samples = 0;
  std::vector<AovPixelSums> pixels;  // row-major
  uint64_t nonFinite = 0;            // CPU: AOV samples left out for a NaN or Inf (a bug if > 0)
};

// One pixel's AOV-pass values: albedo, normal and box tests averaged over the samples;
// depth and position over the samples that hit (0 when none did).
struct AovPixel {
  glm::vec3 albedo, normal, position;
  float depth, boxTests;
};
AovPixel ResolveAovPixel(const AovPixelSums& sums, uint32_t samples);

// A render in progress on either backend. Samples are added in passes to sums that persist
// between them, each pixel's in sample order, so a render of n samples made in any number
// of passes is bit-identical to one pass of n.
class FrameRenderer {
 public:
  virtual ~FrameRenderer() = default;
  // Adds samples [begin, begin + count) to every pixel i with active[i] != 0, or to
  // every pixel when `active` is empty. `progress`, if set, receives the finished
  // fraction of the pass now and then, on the calling thread.
  virtual void AddSamples(uint32_t begin, uint32_t count, std::span<const uint8_t> active,
                          const std::function<void(double)>& progress) = 0;
  // Adds the sums so far (Vulkan: read back) to `into` as AddChunk adds a chunk's: an empty `into` takes this frame's
  // size. No copy of the frame is made.
  virtual void AddSumsTo(FrameSums& into) = 0;
  FrameSums Sums() {
    FrameSums sums;
    AddSumsTo(sums);
    return sums;
  }
  // Zeroes the sums and counters: the next samples start new sums (a chunk's, chunked_frame.h).
  virtual void Clear() = 0;
  // The AOVs of samples [0, request.samples) of every pixel, the camera rays of the
  // render's first samples (shaders/shared/aov.h); independent of the passes so far.
  virtual AovSums RenderAovs(const AovRequest& request) = 0;
  virtual std::string Engine() const = 0;  // for reports: "cpu (2 threads)", "vulkan: <device> (…)"
};

// What a finished render returns.
struct RenderResult {
  Image image;                        // from a Film: mean and variance of the mean per pixel
  uint64_t rays = 0;                  // closest-hit and shadow rays traced
  uint64_t nonFinite = 0;             // as FrameSums::nonFinite
  uint64_t cutShort = 0;              // as FrameSums::cutShort
  double seconds = 0.0;               // rendering alone (Vulkan: dispatches and readback)
  std::string engine;                 // for reports: "cpu (2 threads)", "vulkan: <device> (up to …)"
  unsigned threads = 0;               // CPU: threads used
  uint32_t batches = 0;               // Vulkan: submissions
  uint32_t samplesPerInvocation = 0;  // Vulkan: the longest run of samples per invocation
};

}  // namespace vkpt::internal

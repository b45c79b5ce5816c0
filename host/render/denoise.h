// --denoise: vkpt's à-trous filter (shaders/shared/denoise.h) on an image and its AOVs.
// PrepareDenoise divides the image by its albedo and gathers the guides; either backend
// runs the iterations (AtrousCpu here, vk::AtrousGpu on a device); FinishDenoise
// multiplies the albedo back.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"
#include "render/film.h"

namespace vkpt::internal {

struct DenoiseInput {
  uint32_t width = 0, height = 0;
  std::vector<glm::vec4> color;   // demodulated RGB, variance of its luminance
  std::vector<glm::vec4> guide;   // normal, depth
  std::vector<glm::vec4> albedo;  // the albedo divided out (at least kMinAlbedo per channel), 0
};

// Albedo below this (a black surface, a dark background) is divided out as this, so the
// division stays finite and is undone exactly.
constexpr float kMinAlbedo = 1e-3f;

// `image` must carry its variance; `aovs` are the AOV pass's sums of the same frame.
DenoiseInput PrepareDenoise(const Image& image, const AovSums& aovs);

// Asked before each of the filter's iterations: true abandons the filter.
using StopFilter = std::function<bool()>;

// Every iteration on the CPU; returns the filtered colour (RGB, variance), or nothing once
// `stop` said so.
std::optional<std::vector<glm::vec4>> AtrousCpu(const DenoiseInput& input, unsigned threads = 0,
                                                const StopFilter& stop = {});

// The filtered colour times the albedo again: the denoised image (with the filtered
// variance).
Image FinishDenoise(const DenoiseInput& input, const std::vector<glm::vec4>& filtered);

}  // namespace vkpt::internal

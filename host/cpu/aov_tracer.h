// The CPU's AOVs: shaders/shared/aov.h over every pixel, on util/parallel.h's threads.
#pragma once

#include <cstdint>

#include "render/film.h"
#include "render/render_scene.h"

namespace vkpt {

// Samples [0, samples) of every pixel's AOVs, each pixel's summed in sample order (the
// same sums for any thread count). `scene` must be prepared for the CPU.
AovSums RenderAovsCpu(const RenderScene& scene, const shader::FrameParams& params, uint32_t samples, unsigned threads);

}  // namespace vkpt

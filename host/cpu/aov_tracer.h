// The CPU's AOVs: shaders/shared/aov.h over every pixel, on util/parallel.h's threads.
#pragma once

#include <cstdint>

#include "render/film.h"
#include "render/render_scene.h"

namespace vkpt::internal {

// The AOV pass of every pixel (render/film.h's AovRequest), each pixel's samples summed in
// sample order (the same sums for any thread count). `scene` must be prepared for the CPU.
AovSums RenderAovsCpu(const RenderScene& scene, const shader::FrameParams& params, const AovRequest& request,
                      unsigned threads);

}  // namespace vkpt::internal

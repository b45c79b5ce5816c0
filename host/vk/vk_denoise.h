// The à-trous denoiser (render/denoise.h) on a Vulkan device: denoise.comp, the shared
// filter of shaders/shared/denoise.h, one dispatch per iteration between two buffers.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "render/denoise.h"
#include "vk/context.h"

namespace vkpt::internal::vk {

// Every iteration; returns the filtered colour (RGB, variance), as AtrousCpu does.
// Each iteration is a submission of its own, so that `stop` is asked between them.
std::optional<std::vector<glm::vec4>> AtrousGpu(const Context& ctx, const DenoiseInput& input,
                                                const StopFilter& stop = {});

}  // namespace vkpt::internal::vk

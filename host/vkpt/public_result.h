// A view's render given back in the public types of vkpt/vkpt.h: what Scene::Render and
// View::Result return.
#pragma once

#include <string>

#include "vkpt/view.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal {

// The image (denoised where the options asked), the raw image beside it, the AOVs and
// the render's figures. `rendered`'s layers move into the result.
vkpt::RenderResult PublicResult(const BegunView& view, RenderedView& rendered);

// What ended a frame, as RenderResult::stoppedBy spells it.
std::string PublicStopReason(StopReason reason);

}  // namespace vkpt::internal

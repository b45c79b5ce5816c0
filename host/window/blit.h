// The commands that put a frame's pixels on a swapchain image: the staging buffer copied
// to the staging image, which is blitted (scaled, RGBA → the swapchain's channel order)
// onto the swapchain image, left in COLOR_ATTACHMENT_OPTIMAL for the overlay's pass.
//
// Aspect ratio: kept. The picture is scaled to the largest rectangle of its aspect that
// fits the framebuffer, centred, with black bars on the two other sides (letterbox or
// pillarbox), so a window of another shape never distorts the render.
#pragma once

#include <cstdint>

#include "vk/vk_check.h"
#include "window/staging.h"

namespace vkpt::internal {

// A rectangle of pixels, [x0, x1) × [y0, y1), y down.
struct PixelRect {
  int32_t x0, y0, x1, y1;
};

// Where an image of `src` pixels lands in a framebuffer of `dst` pixels (see above): the
// whole framebuffer when the aspect ratios agree to the pixel.
PixelRect FitRect(VkExtent2D src, VkExtent2D dst);

// Records: staging buffer → staging image, the swapchain `target` (in any layout, its
// contents discarded) cleared to black where the picture does not reach, the blit with
// `filter`, and the barrier that leaves `target` in COLOR_ATTACHMENT_OPTIMAL, its writes
// visible to the overlay pass's load. `target`'s first use waits at the TRANSFER stage,
// where the acquire semaphore's wait must be.
void RecordBlit(VkCommandBuffer cb, const StagingImage& staging, VkImage target, VkExtent2D extent, VkFilter filter);

}  // namespace vkpt::internal

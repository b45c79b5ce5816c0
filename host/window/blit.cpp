#include "window/blit.h"

#include <algorithm>

namespace vkpt::internal {
namespace {

constexpr VkImageSubresourceRange kColour{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};

void Barrier(VkCommandBuffer cb, VkImage image, VkImageLayout from, VkImageLayout to, VkPipelineStageFlags srcStage,
             VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
  VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  b.srcAccessMask = srcAccess;
  b.dstAccessMask = dstAccess;
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = kColour;
  vkCmdPipelineBarrier(cb, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

// The staging buffer's bytes into the staging image, which ends as a blit source. The
// last frame's blit read the image: its TRANSFER stage is waited for (write after read).
void Upload(VkCommandBuffer cb, const StagingImage& staging) {
  constexpr VkPipelineStageFlags transfer = VK_PIPELINE_STAGE_TRANSFER_BIT;
  Barrier(cb, staging.Image(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, transfer, 0, transfer,
          VK_ACCESS_TRANSFER_WRITE_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {staging.Width(), staging.Height(), 1};
  vkCmdCopyBufferToImage(cb, staging.Buffer(), staging.Image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  Barrier(cb, staging.Image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, transfer,
          VK_ACCESS_TRANSFER_WRITE_BIT, transfer, VK_ACCESS_TRANSFER_READ_BIT);
}

}  // namespace

PixelRect FitRect(VkExtent2D src, VkExtent2D dst) {
  // src.w / src.h against dst.w / dst.h in 64-bit integers, without rounding. The scaled
  // side is rounded to the nearest pixel, which cannot exceed the framebuffer's side.
  const uint64_t sw = src.width, sh = src.height, dw = dst.width, dh = dst.height;
  if (sw * dh >= dw * sh) {  // as wide as the framebuffer or wider: full width, bars above and below
    const int32_t h = int32_t(std::max<uint64_t>(1, (dw * sh + sw / 2) / sw));
    const int32_t y0 = (int32_t(dh) - h) / 2;
    return {0, y0, int32_t(dw), y0 + h};
  }
  const int32_t w = int32_t(std::max<uint64_t>(1, (dh * sw + sh / 2) / sh));
  const int32_t x0 = (int32_t(dw) - w) / 2;
  return {x0, 0, x0 + w, int32_t(dh)};
}

void RecordBlit(VkCommandBuffer cb, const StagingImage& staging, VkImage target, VkExtent2D extent, VkFilter filter) {
  constexpr VkPipelineStageFlags transfer = VK_PIPELINE_STAGE_TRANSFER_BIT;
  Upload(cb, staging);
  Barrier(cb, target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, transfer, 0, transfer,
          VK_ACCESS_TRANSFER_WRITE_BIT);
  const PixelRect r = FitRect({staging.Width(), staging.Height()}, extent);
  if (r.x0 > 0 || r.y0 > 0 || r.x1 < int32_t(extent.width) || r.y1 < int32_t(extent.height)) {
    const VkClearColorValue black{{0.0f, 0.0f, 0.0f, 1.0f}};
    vkCmdClearColorImage(cb, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &black, 1, &kColour);
    Barrier(cb, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, transfer,
            VK_ACCESS_TRANSFER_WRITE_BIT, transfer, VK_ACCESS_TRANSFER_WRITE_BIT);
  }
  // Row 0 of the caller's pixels is the top row, and so is row 0 of a swapchain image:
  // no flip. The blit converts RGBA to the swapchain's order (BGRA) by the formats alone.
  VkImageBlit blit{};
  blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.srcOffsets[1] = {int32_t(staging.Width()), int32_t(staging.Height()), 1};
  blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.dstOffsets[0] = {r.x0, r.y0, 0};
  blit.dstOffsets[1] = {r.x1, r.y1, 1};
  vkCmdBlitImage(cb, staging.Image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, filter);
  Barrier(cb, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, transfer,
          VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
          VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
}

}  // namespace vkpt::internal

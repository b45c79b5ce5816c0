#include "window/swapchain.h"

#include <algorithm>
#include <string>

#include "util/error.h"

namespace vkpt::internal {
namespace {

VkSurfaceFormatKHR ChooseFormat(VkPhysicalDevice physical, VkSurfaceKHR surface) {
  uint32_t n = 0;
  VKPT_VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &n, nullptr));
  std::vector<VkSurfaceFormatKHR> formats(n);
  VKPT_VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &n, formats.data()));
  for (VkFormat want : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM})
    for (const VkSurfaceFormatKHR& f : formats)
      if (f.format == want && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
  std::string offered;
  for (const VkSurfaceFormatKHR& f : formats) offered += (offered.empty() ? "" : ", ") + std::to_string(f.format);
  throw Error("the window's surface offers no B8G8R8A8_UNORM or R8G8B8A8_UNORM format (VkFormat values offered: " +
              offered + ")");
}

// MAILBOX, else IMMEDIATE, else FIFO (see swapchain.h).
VkPresentModeKHR ChoosePresentMode(VkPhysicalDevice physical, VkSurfaceKHR surface) {
  uint32_t n = 0;
  VKPT_VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &n, nullptr));
  std::vector<VkPresentModeKHR> modes(n);
  VKPT_VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &n, modes.data()));
  for (VkPresentModeKHR want : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
    if (std::find(modes.begin(), modes.end(), want) != modes.end()) return want;
  return VK_PRESENT_MODE_FIFO_KHR;
}

// The overlay's pass: the blit leaves the image in COLOR_ATTACHMENT_OPTIMAL (a barrier
// before the pass makes its writes visible), the pass loads it, ImGui draws over it, and
// the pass's end leaves it ready to present.
VkRenderPass CreateRenderPass(VkDevice device, VkFormat format) {
  VkAttachmentDescription attachment{};
  attachment.format = format;
  attachment.samples = VK_SAMPLE_COUNT_1_BIT;
  attachment.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  attachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  attachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachment.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  attachment.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  VkAttachmentReference colour{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colour;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 1;
  info.pAttachments = &attachment;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  VkRenderPass pass = VK_NULL_HANDLE;
  VKPT_VK_CHECK(vkCreateRenderPass(device, &info, nullptr, &pass));
  return pass;
}

}  // namespace

Swapchain::Swapchain(const PresentDevice& device, VkExtent2D framebuffer) : device_(device) {
  format_ = ChooseFormat(device.Physical(), device.Surface());
  presentMode_ = ChoosePresentMode(device.Physical(), device.Surface());
  VkFormatProperties props;
  vkGetPhysicalDeviceFormatProperties(device.Physical(), format_.format, &props);
  if (!(props.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT))
    throw Error("the Vulkan device " + device.Name() + " cannot blit to the window's image format");
  renderPass_ = CreateRenderPass(device.Device(), format_.format);
  try {
    Create(framebuffer);
  } catch (...) {
    Release();
    throw;
  }
}

Swapchain::~Swapchain() { Release(); }

void Swapchain::Release() {
  DestroyImages();
  if (swapchain_) vkDestroySwapchainKHR(device_.Device(), swapchain_, nullptr);
  if (renderPass_) vkDestroyRenderPass(device_.Device(), renderPass_, nullptr);
  swapchain_ = VK_NULL_HANDLE, renderPass_ = VK_NULL_HANDLE;
}

void Swapchain::Recreate(VkExtent2D framebuffer) {
  VKPT_VK_CHECK(vkDeviceWaitIdle(device_.Device()));
  Create(framebuffer);
}

void Swapchain::DestroyImages() {
  const VkDevice device = device_.Device();
  for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(device, f, nullptr);
  for (VkImageView v : views_) vkDestroyImageView(device, v, nullptr);
  for (VkSemaphore s : rendered_) vkDestroySemaphore(device, s, nullptr);
  framebuffers_.clear(), views_.clear(), rendered_.clear(), images_.clear();
}

void Swapchain::Create(VkExtent2D framebuffer) {
  const VkDevice device = device_.Device();
  VkSurfaceCapabilitiesKHR caps;
  VKPT_VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(device_.Physical(), device_.Surface(), &caps));
  if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
    throw Error("the window's swapchain images cannot be a transfer destination on " + device_.Name());
  // X11 and most platforms fix the extent to the window's; Wayland leaves it to us.
  extent_ = caps.currentExtent;
  if (extent_.width == UINT32_MAX)
    extent_ = {std::clamp(framebuffer.width, caps.minImageExtent.width, caps.maxImageExtent.width),
               std::clamp(framebuffer.height, caps.minImageExtent.height, caps.maxImageExtent.height)};
  requested_ = framebuffer;
  // One more than the minimum, so that acquiring never waits for the presentation engine
  // to release the only spare image; at least 2 (ImGui's Vulkan backend asserts it).
  minImageCount_ = std::max(2u, caps.minImageCount + 1);
  if (caps.maxImageCount) minImageCount_ = std::min(minImageCount_, caps.maxImageCount);

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = device_.Surface();
  info.minImageCount = minImageCount_;
  info.imageFormat = format_.format;
  info.imageColorSpace = format_.colorSpace;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  // Opaque where the platform allows it (X11 does); else the first mode it has.
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  for (uint32_t bit = 1; !(caps.supportedCompositeAlpha & info.compositeAlpha) && bit <= 8; bit <<= 1)
    info.compositeAlpha = VkCompositeAlphaFlagBitsKHR(bit);
  info.presentMode = presentMode_;
  info.clipped = VK_TRUE;
  info.oldSwapchain = swapchain_;
  VkSwapchainKHR created = VK_NULL_HANDLE;
  VKPT_VK_CHECK(vkCreateSwapchainKHR(device, &info, nullptr, &created));
  DestroyImages();
  if (swapchain_) vkDestroySwapchainKHR(device, swapchain_, nullptr);
  swapchain_ = created;
  CreateImageObjects();
}

// Each image's view, framebuffer (for the overlay's pass) and "rendered" semaphore.
void Swapchain::CreateImageObjects() {
  const VkDevice device = device_.Device();
  uint32_t n = 0;
  VKPT_VK_CHECK(vkGetSwapchainImagesKHR(device, swapchain_, &n, nullptr));
  images_.resize(n);
  VKPT_VK_CHECK(vkGetSwapchainImagesKHR(device, swapchain_, &n, images_.data()));
  for (VkImage image : images_) {
    VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    viewInfo.image = image;
    viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
    viewInfo.format = format_.format;
    viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VKPT_VK_CHECK(vkCreateImageView(device, &viewInfo, nullptr, &views_.emplace_back()));
    VkFramebufferCreateInfo fbInfo{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fbInfo.renderPass = renderPass_;
    fbInfo.attachmentCount = 1;
    fbInfo.pAttachments = &views_.back();
    fbInfo.width = extent_.width;
    fbInfo.height = extent_.height;
    fbInfo.layers = 1;
    VKPT_VK_CHECK(vkCreateFramebuffer(device, &fbInfo, nullptr, &framebuffers_.emplace_back()));
    VkSemaphoreCreateInfo semInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VKPT_VK_CHECK(vkCreateSemaphore(device, &semInfo, nullptr, &rendered_.emplace_back()));
  }
}

}  // namespace vkpt::internal

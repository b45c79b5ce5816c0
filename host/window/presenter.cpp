#include "window/presenter.h"

#include <atomic>
#include <cstdlib>
#include <cstring>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "util/error.h"
#include "vk/vk_check.h"
#include "window/blit.h"
#include "window/overlay.h"
#include "window/present_device.h"
#include "window/staging.h"
#include "window/swapchain.h"

namespace vkpt::internal {
namespace {

// GLFW reports errors through a callback, not through return values: the last one is kept
// for the Error that follows a failed call.
std::string lastGlfwError;
void OnGlfwError(int code, const char* what) { lastGlfwError = what ? what : "error " + std::to_string(code); }

bool Set(const char* name) {
  const char* value = std::getenv(name);
  return value && *value;
}

// GLFW, initialised for the Presenter's life. GLFW and ImGui keep one state per process,
// so a second Presenter while one is alive is refused.
std::atomic<bool> presenterAlive{false};
struct GlfwSession {
  GlfwSession() {
    if (presenterAlive.exchange(true)) throw Error("a window is already open: one Presenter at a time");
    glfwSetErrorCallback(&OnGlfwError);
    lastGlfwError.clear();
    if (!glfwInit()) {
      presenterAlive = false;
      throw Error("cannot open a window: GLFW failed to start (" + lastGlfwError +
                  "); DISPLAY or WAYLAND_DISPLAY must name a running display server");
    }
    if (!glfwVulkanSupported()) {
      glfwTerminate();
      presenterAlive = false;
      throw Error("cannot open a window: GLFW finds no Vulkan loader (libvulkan.so.1)");
    }
  }
  ~GlfwSession() {
    glfwTerminate();
    presenterAlive = false;
  }
};

GLFWwindow* OpenWindow(const std::string& title, uint32_t width, uint32_t height) {
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);  // Vulkan draws: no OpenGL context
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
  if (!window)
    throw Error("cannot open a window of " + std::to_string(width) + " x " + std::to_string(height) + ": " +
                lastGlfwError);
  return window;
}

// The one frame in flight: its command buffer, the fence its submission signals, and the
// semaphore acquisition signals. Show waits for the fence before reusing any of them, so
// after that wait the last submission has consumed the semaphore too.
struct FrameSync {
  explicit FrameSync(const PresentDevice& device) : device(device.Device()) {
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = device.QueueFamily();
    VKPT_VK_CHECK(vkCreateCommandPool(this->device, &poolInfo, nullptr, &pool));
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VKPT_VK_CHECK(vkAllocateCommandBuffers(this->device, &alloc, &cb));
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;  // the first Show has nothing to wait for
    VKPT_VK_CHECK(vkCreateFence(this->device, &fenceInfo, nullptr, &fence));
    VkSemaphoreCreateInfo semInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VKPT_VK_CHECK(vkCreateSemaphore(this->device, &semInfo, nullptr, &acquired));
  }
  ~FrameSync() {
    if (acquired) vkDestroySemaphore(device, acquired, nullptr);
    if (fence) vkDestroyFence(device, fence, nullptr);
    if (pool) vkDestroyCommandPool(device, pool, nullptr);
  }
  VkDevice device;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer cb = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  VkSemaphore acquired = VK_NULL_HANDLE;
};

bool operator!=(VkExtent2D a, VkExtent2D b) { return a.width != b.width || a.height != b.height; }

// Acquisition does not wait forever: a window system that never releases an image
// becomes an Error rather than a hung viewer.
constexpr uint64_t kAcquireTimeoutNs = 10'000'000'000;

}  // namespace

std::optional<std::string> NoDisplayReason() {
  if (Set("DISPLAY") || Set("WAYLAND_DISPLAY")) return std::nullopt;
  return "no display: neither DISPLAY nor WAYLAND_DISPLAY is set (the viewer needs an X11 or Wayland display; "
         "under CI run it in Xvfb)";
}

// Members in the order of creation, so that they are destroyed in reverse; ~State waits
// for the device first.
struct Presenter::State {
  State(const std::string& title, uint32_t width, uint32_t height, const std::string& deviceName, bool validation)
      : window(OpenWindow(title, width, height), &glfwDestroyWindow),
        device(window.get(), deviceName, validation),
        swapchain(device, CurrentFramebuffer()),
        overlay(window.get(), device, swapchain),
        frame(device) {
    VkFormatProperties props;
    vkGetPhysicalDeviceFormatProperties(device.Physical(), StagingImage::kFormat, &props);
    if (!(props.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_SRC_BIT))
      throw Error("the Vulkan device " + device.Name() + " cannot blit from RGBA8 images");
    filter = (props.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) ? VK_FILTER_LINEAR
                                                                                               : VK_FILTER_NEAREST;
  }
  ~State() { vkDeviceWaitIdle(device.Device()); }

  VkExtent2D CurrentFramebuffer() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window.get(), &w, &h);
    return {uint32_t(std::max(w, 0)), uint32_t(std::max(h, 0))};
  }
  void Recreate(VkExtent2D framebuffer) {
    swapchain.Recreate(framebuffer);
    overlay.SetMinImageCount(swapchain.MinImageCount());
    recreate = false;
  }
  // The next swapchain image (recreating the swapchain once if it is out of date), or
  // nothing when it is still out of date.
  std::optional<uint32_t> Acquire(VkExtent2D framebuffer);
  void Submit(uint32_t image);

  GlfwSession glfw;
  std::unique_ptr<GLFWwindow, void (*)(GLFWwindow*)> window;
  PresentDevice device;
  Swapchain swapchain;
  Overlay overlay;
  FrameSync frame;
  std::unique_ptr<StagingImage> staging;  // kept while the image size is unchanged
  VkFilter filter = VK_FILTER_LINEAR;
  bool recreate = false;  // the last present said out of date or suboptimal
};

std::optional<uint32_t> Presenter::State::Acquire(VkExtent2D framebuffer) {
  for (int attempt = 0; attempt < 2; ++attempt) {
    uint32_t image = 0;
    const VkResult r = vkAcquireNextImageKHR(device.Device(), swapchain.Handle(), kAcquireTimeoutNs, frame.acquired,
                                             VK_NULL_HANDLE, &image);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) {
      Recreate(framebuffer);
      continue;
    }
    if (r == VK_SUBOPTIMAL_KHR) {
      recreate = true;  // still usable (and the semaphore is signalled): shown, then recreated
      return image;
    }
    VKPT_VK_CHECK(r);
    return image;
  }
  return std::nullopt;
}

void Presenter::State::Submit(uint32_t image) {
  VkCommandBuffer cb = frame.cb;
  VKPT_VK_CHECK(vkResetCommandBuffer(cb, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VKPT_VK_CHECK(vkBeginCommandBuffer(cb, &begin));
  RecordBlit(cb, *staging, swapchain.Image(image), swapchain.Extent(), filter);
  overlay.Record(cb, swapchain.RenderPass(), swapchain.Framebuffer(image), swapchain.Extent());
  VKPT_VK_CHECK(vkEndCommandBuffer(cb));

  // The image's first use is the blit's barrier at TRANSFER: the acquire wait is there.
  const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
  const VkSemaphore rendered = swapchain.Rendered(image);
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.waitSemaphoreCount = 1;
  submit.pWaitSemaphores = &frame.acquired;
  submit.pWaitDstStageMask = &waitStage;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cb;
  submit.signalSemaphoreCount = 1;
  submit.pSignalSemaphores = &rendered;
  VKPT_VK_CHECK(vkResetFences(device.Device(), 1, &frame.fence));
  VKPT_VK_CHECK(vkQueueSubmit(device.Queue(), 1, &submit, frame.fence));

  // One "rendered" semaphore per swapchain image: the image's next acquisition proves
  // that the presentation engine has finished waiting on it.
  const VkSwapchainKHR handle = swapchain.Handle();
  VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  present.waitSemaphoreCount = 1;
  present.pWaitSemaphores = &rendered;
  present.swapchainCount = 1;
  present.pSwapchains = &handle;
  present.pImageIndices = &image;
  const VkResult r = vkQueuePresentKHR(device.Queue(), &present);
  if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) recreate = true;
  else VKPT_VK_CHECK(r);
}

Presenter::Presenter(const std::string& title, uint32_t width, uint32_t height, const std::string& device,
                     bool validation) {
  if (width == 0 || height == 0) throw Error("a window needs a size of at least 1 x 1");
  if (const std::optional<std::string> reason = NoDisplayReason()) throw Error("cannot open a window: " + *reason);
  state_ = std::make_unique<State>(title, width, height, device, validation);
}

Presenter::~Presenter() = default;

GLFWwindow* Presenter::Window() const { return state_->window.get(); }

glm::uvec2 Presenter::FramebufferSize() const {
  const VkExtent2D e = state_->CurrentFramebuffer();
  return {e.width, e.height};
}

bool Presenter::ShouldClose() const { return glfwWindowShouldClose(state_->window.get()); }

std::string Presenter::DeviceName() const { return state_->device.Name(); }

const char* Presenter::PresentModeName() const {
  switch (state_->swapchain.PresentMode()) {
    case VK_PRESENT_MODE_MAILBOX_KHR: return "mailbox";
    case VK_PRESENT_MODE_IMMEDIATE_KHR: return "immediate";
    default: return "fifo";
  }
}

uint32_t Presenter::ValidationMessages() const { return state_->device.ValidationMessages(); }

void Presenter::BeginOverlay() { state_->overlay.Begin(); }

void Presenter::Show(std::span<const uint8_t> rgba, uint32_t width, uint32_t height) {
  State& s = *state_;
  if (width == 0 || height == 0 || rgba.size() != size_t(width) * height * 4)
    throw Error("Presenter::Show: " + std::to_string(rgba.size()) + " bytes are not " + std::to_string(width) + " x " +
                std::to_string(height) + " RGBA pixels");
  const VkExtent2D framebuffer = s.CurrentFramebuffer();
  if (framebuffer.width == 0 || framebuffer.height == 0) {  // minimised
    s.overlay.Discard();
    return;
  }
  // One frame in flight: the last one's commands are done with the staging objects, the
  // command buffer and the acquire semaphore after this.
  VKPT_VK_CHECK(vkWaitForFences(s.device.Device(), 1, &s.frame.fence, VK_TRUE, UINT64_MAX));
  if (s.recreate || framebuffer != s.swapchain.Requested()) s.Recreate(framebuffer);
  const std::optional<uint32_t> image = s.Acquire(framebuffer);
  if (!image) {
    s.overlay.Discard();
    return;
  }
  if (!s.staging || s.staging->Width() != width || s.staging->Height() != height) {
    s.staging.reset();
    s.staging = std::make_unique<StagingImage>(s.device, width, height);
  }
  std::memcpy(s.staging->Mapped(), rgba.data(), rgba.size());
  s.Submit(*image);
}

}  // namespace vkpt::internal

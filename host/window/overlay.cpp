#include "window/overlay.h"

#include <imgui/backends/imgui_impl_glfw.h>
#include <imgui/backends/imgui_impl_vulkan.h>
#include <imgui/imgui.h>

#include "util/error.h"

namespace vkpt::internal {
namespace {

// ImGui's Vulkan backend reports each VkResult here; a failure becomes an Error.
void CheckImGuiResult(VkResult r) { vk::Check(r, "ImGui's Vulkan backend"); }

// The pool ImGui's Vulkan backend takes its descriptor sets from: 1.86 needs one, for
// the font atlas; a few more cost nothing.
VkDescriptorPool CreatePool(VkDevice device) {
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 8};
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  info.maxSets = 8;
  info.poolSizeCount = 1;
  info.pPoolSizes = &size;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VKPT_VK_CHECK(vkCreateDescriptorPool(device, &info, nullptr, &pool));
  return pool;
}

}  // namespace

Overlay::Overlay(GLFWwindow* window, const PresentDevice& device, const Swapchain& swapchain)
    : device_(device.Device()) {
  try {
    pool_ = CreatePool(device_);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    context_ = true;
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // a viewer's overlay keeps no layout between runs
    ImGui::StyleColorsDark();
    if (!ImGui_ImplGlfw_InitForVulkan(window, true)) throw Error("ImGui's GLFW backend failed to start");
    glfw_ = true;
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = device.Instance();
    info.PhysicalDevice = device.Physical();
    info.Device = device_;
    info.QueueFamily = device.QueueFamily();
    info.Queue = device.Queue();
    info.PipelineCache = VK_NULL_HANDLE;
    info.DescriptorPool = pool_;
    info.Subpass = 0;
    info.MinImageCount = swapchain.MinImageCount();
    info.ImageCount = swapchain.ImageCount();
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.Allocator = nullptr;
    info.CheckVkResultFn = &CheckImGuiResult;
    if (!ImGui_ImplVulkan_Init(&info, swapchain.RenderPass())) throw Error("ImGui's Vulkan backend failed to start");
    vulkan_ = true;
    UploadFonts(device);
  } catch (...) {
    Release();
    throw;
  }
}

Overlay::~Overlay() { Release(); }

void Overlay::Release() {
  if (begun_) ImGui::EndFrame();
  if (vulkan_) ImGui_ImplVulkan_Shutdown();
  if (glfw_) ImGui_ImplGlfw_Shutdown();
  if (context_) ImGui::DestroyContext();
  if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);
  begun_ = vulkan_ = glfw_ = context_ = false;
  pool_ = VK_NULL_HANDLE;
}

// The font atlas, rasterised by ImGui and copied to an image by one command buffer that
// is waited for, after which its staging buffer is freed.
void Overlay::UploadFonts(const PresentDevice& device) {
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  poolInfo.queueFamilyIndex = device.QueueFamily();
  VkCommandPool pool = VK_NULL_HANDLE;
  VKPT_VK_CHECK(vkCreateCommandPool(device_, &poolInfo, nullptr, &pool));
  try {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cb = VK_NULL_HANDLE;
    VKPT_VK_CHECK(vkAllocateCommandBuffers(device_, &alloc, &cb));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VKPT_VK_CHECK(vkBeginCommandBuffer(cb, &begin));
    if (!ImGui_ImplVulkan_CreateFontsTexture(cb)) throw Error("ImGui could not create its font texture");
    VKPT_VK_CHECK(vkEndCommandBuffer(cb));
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cb;
    VKPT_VK_CHECK(vkQueueSubmit(device.Queue(), 1, &submit, VK_NULL_HANDLE));
    VKPT_VK_CHECK(vkQueueWaitIdle(device.Queue()));
    ImGui_ImplVulkan_DestroyFontUploadObjects();
  } catch (...) {
    vkDestroyCommandPool(device_, pool, nullptr);
    throw;
  }
  vkDestroyCommandPool(device_, pool, nullptr);
}

void Overlay::Begin() {
  Discard();
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  begun_ = true;
}

void Overlay::Discard() {
  if (begun_) ImGui::EndFrame();
  begun_ = false;
}

void Overlay::Record(VkCommandBuffer cb, VkRenderPass pass, VkFramebuffer framebuffer, VkExtent2D extent) {
  VkRenderPassBeginInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  info.renderPass = pass;
  info.framebuffer = framebuffer;
  info.renderArea = {{0, 0}, extent};
  vkCmdBeginRenderPass(cb, &info, VK_SUBPASS_CONTENTS_INLINE);
  if (begun_) {
    ImGui::Render();
    ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cb);
    begun_ = false;
  }
  vkCmdEndRenderPass(cb);
}

void Overlay::SetMinImageCount(uint32_t count) { ImGui_ImplVulkan_SetMinImageCount(count); }

}  // namespace vkpt::internal

// A window that shows images: GLFW's window, a Vulkan swapchain of its own and a Dear
// ImGui overlay. The interactive viewer shows each render with it; the renderer's device
// is not involved (the presenter has its own instance and device, as presenting needs
// surface extensions a headless vk::Context does not have).
#pragma once

#include <glm/vec2.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>

struct GLFWwindow;

namespace vkpt::internal {

// Why no window can open, or nothing: neither DISPLAY nor WAYLAND_DISPLAY is set. Checked
// first, so that a viewer fails at once (exit 2) rather than after loading a scene.
std::optional<std::string> NoDisplayReason();

class Presenter {
 public:
  // Opens a resizable window of width × height screen coordinates titled `title`, with a
  // Vulkan instance with the surface extensions, the first device that can present to it
  // (or the first whose name contains `device`, when that is not empty), a swapchain and
  // Dear ImGui (GLFW and Vulkan backends, dark style, no .ini file). With `validation`,
  // the Vulkan validation layer checks every call and ValidationMessages() counts what it
  // reports. Throws Error when GLFW cannot start (no display), no device can present, or
  // another Presenter is alive (GLFW and ImGui hold one state per process).
  Presenter(const std::string& title, uint32_t width, uint32_t height, const std::string& device = "",
            bool validation = false);
  // Waits for the device to be idle, destroys everything and terminates GLFW.
  ~Presenter();
  Presenter(const Presenter&) = delete;
  Presenter& operator=(const Presenter&) = delete;

  GLFWwindow* Window() const;
  glm::uvec2 FramebufferSize() const;  // pixels (0 × 0 while minimised)
  bool ShouldClose() const;
  std::string DeviceName() const;
  const char* PresentModeName() const;  // "mailbox", "immediate" or "fifo"
  uint32_t ValidationMessages() const;  // warnings and errors so far; 0 without validation

  // Starts an ImGui frame: the caller then issues ImGui calls, which the next Show draws.
  void BeginOverlay();

  // Shows `rgba` (width × height pixels, 8-bit RGBA, display-encoded, row-major from the
  // top row) scaled to the framebuffer with its aspect ratio kept (black bars where the
  // shapes differ; linear filtering), then the overlay begun by BeginOverlay on top, and
  // presents it. Recreates the swapchain when the window was resized or the swapchain is
  // out of date or suboptimal; a minimised (0 × 0) window shows nothing and returns at
  // once. One frame is in flight: Show waits for the previous frame's commands first.
  // Throws Error when rgba is not width × height × 4 bytes.
  void Show(std::span<const uint8_t> rgba, uint32_t width, uint32_t height);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace vkpt::internal

// An X server for the tests that open windows: Xvfb (a virtual framebuffer, no window
// manager) on a display of its own, and the external tools that read its screen back
// (xwininfo, ImageMagick's import) and send it input (xdotool, through XTEST).
//
// Why these tools: a Vulkan window's pixels are read from the root window and cropped to
// the window's geometry, since `import -window WID` returns a near-empty image for one;
// keys and drags go through XTEST with the pointer over the window (focus follows the
// pointer without a window manager), since GLFW ignores XSendEvent's synthetic events
// (`xdotool key --window`). Every command runs under `timeout 10`.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vkpt::internal::test {

// An environment variable set (or unset, with nullopt) for a scope, then restored.
class ScopedEnv {
 public:
  ScopedEnv(const std::string& name, const std::optional<std::string>& value);
  ~ScopedEnv();
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  std::string name_;
  std::optional<std::string> old_;
};

// A top-level window's place on the screen.
struct WindowGeometry {
  uint64_t id = 0;
  int x = 0, y = 0;
  uint32_t width = 0, height = 0;
};

class XServer {
 public:
  // Starts `Xvfb :N -screen 0 <width>x<height>x24 -nolisten tcp` on the first display
  // number from 90 up whose socket and lock file are absent and that Xvfb can take
  // (another test process may race for it), and waits at most 10 s until it accepts
  // connections (Xvfb's -displayfd says so). While alive, DISPLAY names it and
  // WAYLAND_DISPLAY is unset. Missing tools: Skipped() says which; a server that does
  // not start: Error() says why.
  explicit XServer(uint32_t width = 800, uint32_t height = 600);
  // Stops the server (SIGTERM, then SIGKILL after 5 s) and restores the environment.
  ~XServer();
  XServer(const XServer&) = delete;
  XServer& operator=(const XServer&) = delete;

  bool Running() const { return pid_ > 0; }
  const std::string& Skipped() const { return skipped_; }  // why the tests cannot run here; "" if they can
  const std::string& Error() const { return error_; }      // why the server did not start
  std::string Display() const { return ":" + std::to_string(number_); }

  // The top-level window titled `title` (xwininfo -name), or nothing.
  std::optional<WindowGeometry> FindWindow(const std::string& title) const;
  // The pixels on screen where the window titled `title` is, 8-bit RGB, top row first;
  // its size in `width` × `height`. Empty (and 0 × 0) when there is no such window or the
  // read fails.
  std::vector<uint8_t> ReadWindowRGB(const std::string& title, uint32_t& width, uint32_t& height) const;
  // `xdotool mousemove --window WID 40 40 <verb> <keys...>` (verb: key, keydown, keyup).
  bool SendKeys(const std::string& title, const std::vector<std::string>& keys, const std::string& verb = "key") const;
  // A drag with button 1 from (x0, y0) to (x1, y1), in the window's coordinates, through
  // `steps` intermediate pointer moves.
  bool MouseDrag(const std::string& title, int x0, int y0, int x1, int y1, int steps = 4) const;
  // A click of button 1 at (x, y) in the window's coordinates, the pointer resting there
  // first so that the window has seen it arrive.
  bool MouseClick(const std::string& title, int x, int y) const;

 private:
  bool Start(uint32_t width, uint32_t height);
  bool Xdotool(const std::vector<std::string>& args) const;

  pid_t pid_ = -1;
  int number_ = -1;
  std::string skipped_, error_;
  std::optional<ScopedEnv> display_, wayland_;
};

// Skips the test (a macro: GTEST_SKIP returns from the test) when the tools are missing;
// fails it when they are there but the server did not start.
#define VKPT_REQUIRE_X_SERVER(server)                                    \
  do {                                                                   \
    if (!(server).Skipped().empty()) GTEST_SKIP() << (server).Skipped(); \
    ASSERT_TRUE((server).Running()) << (server).Error();                 \
  } while (0)

}  // namespace vkpt::internal::test

// The window that shows images (window/presenter.h), under Xvfb on lavapipe with the
// validation layer: the pixels on the X server's screen are read back and must be the
// image's (top row first, channels in order), at the window's new size after a resize,
// letterboxed when the shapes differ, with ImGui's overlay only where its window is; keys
// and drags sent through XTEST reach the window; every run is free of validation
// messages. Without a display, the presenter refuses at once with a message naming
// DISPLAY and WAYLAND_DISPLAY.
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui/imgui.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <optional>
#include <thread>

#include "test_util.h"
#include "util/error.h"
#include "window/blit.h"
#include "window/presenter.h"
#include "x_server.h"

namespace vkpt::internal {
namespace {

using test::XServer;

struct Rgb {
  int r, g, b;
};
constexpr Rgb kRed{255, 0, 0}, kBlue{0, 0, 255}, kGreen{0, 255, 0}, kBlack{0, 0, 0};

// The test picture, w × h RGBA: the left half red, the right half blue, and a 4 × 4 green
// square at the top left, which lands at the bottom left if rows are flipped.
std::vector<uint8_t> Halves(uint32_t w, uint32_t h) {
  std::vector<uint8_t> rgba(size_t(w) * h * 4);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const Rgb c = x < 4 && y < 4 ? kGreen : x < w / 2 ? kRed : kBlue;
      uint8_t* p = &rgba[(size_t(y) * w + x) * 4];
      p[0] = uint8_t(c.r), p[1] = uint8_t(c.g), p[2] = uint8_t(c.b), p[3] = 255;
    }
  return rgba;
}

// What Halves(w, ·) shows at (x, y) when drawn 1:1.
Rgb HalvesAt(uint32_t x, uint32_t y, uint32_t w) { return x < 4 && y < 4 ? kGreen : x < w / 2 ? kRed : kBlue; }

struct Screen {
  std::vector<uint8_t> rgb;
  uint32_t width = 0, height = 0;
  Rgb At(uint32_t x, uint32_t y) const {
    const uint8_t* p = &rgb[(size_t(y) * width + x) * 3];
    return {p[0], p[1], p[2]};
  }
};

// "" when every pixel of `s` is within `tolerance` (per channel) of expected(x, y), where
// that is not nullopt (a pixel nobody predicts); else how many differ and the first one.
using Expected = std::function<std::optional<Rgb>(uint32_t x, uint32_t y)>;
std::string Mismatches(const Screen& s, const Expected& expected, int tolerance) {
  if (s.rgb.empty()) return "no pixels read back";
  size_t count = 0;
  std::string first;
  for (uint32_t y = 0; y < s.height; ++y)
    for (uint32_t x = 0; x < s.width; ++x) {
      const std::optional<Rgb> e = expected(x, y);
      const Rgb a = s.At(x, y);
      if (!e ||
          (std::abs(a.r - e->r) <= tolerance && std::abs(a.g - e->g) <= tolerance && std::abs(a.b - e->b) <= tolerance))
        continue;
      if (count++ == 0) {
        char text[160];
        std::snprintf(text, sizeof text, " first at (%u, %u): (%d, %d, %d), expected (%d, %d, %d)", x, y, a.r, a.g, a.b,
                      e->r, e->g, e->b);
        first = text;
      }
    }
  return count ? std::to_string(count) + " pixels differ;" + first : "";
}

void Pump(int times = 3) {
  for (int i = 0; i < times; ++i) {
    glfwPollEvents();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

// Shows `rgba` three times (each time with the overlay `overlay` draws, if any), then reads
// the window back, until the pixels match `expected` or five rounds have passed (the X
// server may not yet hold the last frame); returns the last read.
Screen ShowAndRead(Presenter& p, const XServer& x, const std::string& title, const std::vector<uint8_t>& rgba,
                   glm::uvec2 size, const Expected& expected, const std::function<void()>& overlay = {}) {
  Screen s;
  for (int round = 0; round < 5; ++round) {
    for (int i = 0; i < 3; ++i) {
      if (overlay) {
        p.BeginOverlay();
        overlay();
      }
      p.Show(rgba, size.x, size.y);
      Pump(1);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50 * (round + 1)));
    s.rgb = x.ReadWindowRGB(title, s.width, s.height);
    if (!s.rgb.empty() && Mismatches(s, expected, 3).empty()) break;
  }
  return s;
}

TEST(Window, WithoutADisplayItSaysSoAndRefuses) {
  {
    test::ScopedEnv display("DISPLAY", std::nullopt), wayland("WAYLAND_DISPLAY", std::nullopt);
    const std::optional<std::string> reason = NoDisplayReason();
    ASSERT_TRUE(reason);
    EXPECT_NE(reason->find("DISPLAY"), std::string::npos) << *reason;
    EXPECT_NE(reason->find("WAYLAND_DISPLAY"), std::string::npos) << *reason;
    try {
      Presenter p("vkpt-no-display", 64, 48);
      FAIL() << "a Presenter opened without a display";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("WAYLAND_DISPLAY"), std::string::npos) << e.what();
    }
  }
  {
    // A display that is set but where no server listens: GLFW's own failure, named.
    test::ScopedEnv display("DISPLAY", ":65000"), wayland("WAYLAND_DISPLAY", std::nullopt);
    EXPECT_FALSE(NoDisplayReason());
    try {
      Presenter p("vkpt-no-server", 64, 48);
      FAIL() << "a Presenter opened on a display with no server";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("GLFW"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("DISPLAY"), std::string::npos) << e.what();
    }
  }
}

TEST(Window, ShowsTheImageTopRowFirstWithItsChannelsInOrder) {
  XServer x;
  VKPT_REQUIRE_X_SERVER(x);
  const std::string title = "vkpt-window-halves";
  Presenter p(title, 160, 120, "", true);
  ASSERT_EQ(p.FramebufferSize(), glm::uvec2(160, 120));
  const Expected halves = [](uint32_t x, uint32_t y) { return HalvesAt(x, y, 160); };
  const Screen s = ShowAndRead(p, x, title, Halves(160, 120), {160, 120}, halves);
  ASSERT_EQ(s.width, 160u);
  ASSERT_EQ(s.height, 120u);
  EXPECT_EQ(Mismatches(s, halves, 3), "");
  // The same, spelled out at the points that tell the failures apart.
  EXPECT_NEAR(s.At(40, 60).r, 255, 3) << "the left half is red";
  EXPECT_NEAR(s.At(120, 60).b, 255, 3) << "the right half is blue";
  EXPECT_NEAR(s.At(1, 1).g, 255, 3) << "the green square is at the top left";
  EXPECT_NEAR(s.At(1, 118).r, 255, 3) << "the bottom left is red, not green";
  EXPECT_THROW(p.Show(Halves(160, 120), 161, 120), Error) << "the bytes are not 161 x 120 pixels";
  EXPECT_EQ(p.ValidationMessages(), 0u);
  std::printf("device %s, present mode %s\n", p.DeviceName().c_str(), p.PresentModeName());
}

TEST(Window, AfterAResizeItShowsTheNewSizeAndLetterboxesOtherShapes) {
  XServer x;
  VKPT_REQUIRE_X_SERVER(x);
  const std::string title = "vkpt-window-resize";
  Presenter p(title, 160, 120, "", true);
  ShowAndRead(p, x, title, Halves(160, 120), {160, 120}, [](uint32_t x, uint32_t y) { return HalvesAt(x, y, 160); });
  glfwSetWindowSize(p.Window(), 240, 90);
  for (int i = 0; i < 200 && p.FramebufferSize() != glm::uvec2(240, 90); ++i) Pump(1);
  ASSERT_EQ(p.FramebufferSize(), glm::uvec2(240, 90));

  const Expected wide = [](uint32_t x, uint32_t y) { return HalvesAt(x, y, 240); };
  Screen s = ShowAndRead(p, x, title, Halves(240, 90), {240, 90}, wide);
  ASSERT_EQ(s.width, 240u);
  ASSERT_EQ(s.height, 90u);
  EXPECT_EQ(Mismatches(s, wide, 3), "");

  // The 4:3 picture in the 8:3 window: 120 × 90 pixels in the middle, black bars at the
  // sides (window/blit.h); scaled by 3/4 with linear filtering, so the colours' edges
  // blend and are not predicted.
  const Expected boxed = [](uint32_t x, uint32_t y) -> std::optional<Rgb> {
    if (x < 60 || x >= 180) return kBlack;
    if (x < 63 && y < 3) return kGreen;
    if (x == 63 || y == 3 || x == 119 || x == 120) return std::nullopt;
    return x < 120 ? kRed : kBlue;
  };
  s = ShowAndRead(p, x, title, Halves(160, 120), {160, 120}, boxed);
  EXPECT_EQ(Mismatches(s, boxed, 3), "");
  EXPECT_EQ(p.ValidationMessages(), 0u);
}

TEST(Window, TheOverlayChangesThePixelsOfItsWindowOnly) {
  XServer x;
  VKPT_REQUIRE_X_SERVER(x);
  const std::string title = "vkpt-window-overlay";
  const bool iniBefore = std::filesystem::exists("imgui.ini");
  std::optional<Presenter> presenter(std::in_place, title, 160, 120, "", true);
  Presenter& p = *presenter;
  const Expected halves = [](uint32_t x, uint32_t y) { return HalvesAt(x, y, 160); };
  Screen s = ShowAndRead(p, x, title, Halves(160, 120), {160, 120}, halves);
  ASSERT_EQ(Mismatches(s, halves, 3), "") << "without the overlay";

  // An opaque green ImGui window at (90, 50), 50 × 40, over the red/blue border. Its edge
  // (a 1-pixel border in the dark style) is not predicted.
  const auto box = [] {
    ImGui::SetNextWindowPos(ImVec2(90, 50));
    ImGui::SetNextWindowSize(ImVec2(50, 40));
    ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0, 1, 0, 1));
    ImGui::Begin("box", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs);
    ImGui::End();
    ImGui::PopStyleColor();
  };
  const Expected withBox = [](uint32_t x, uint32_t y) -> std::optional<Rgb> {
    if (x >= 92 && x < 138 && y >= 52 && y < 88) return kGreen;
    if (x >= 88 && x < 142 && y >= 48 && y < 92) return std::nullopt;
    return HalvesAt(x, y, 160);
  };
  s = ShowAndRead(p, x, title, Halves(160, 120), {160, 120}, withBox, box);
  EXPECT_EQ(Mismatches(s, withBox, 3), "");
  EXPECT_EQ(p.ValidationMessages(), 0u);
  presenter.reset();  // ImGui would save its .ini file here at the latest
  if (!iniBefore) {
    EXPECT_FALSE(std::filesystem::exists("imgui.ini")) << "ImGui wrote imgui.ini";
  }
}

TEST(Window, KeysAndDragsThroughXtestReachTheWindow) {
  XServer x;
  VKPT_REQUIRE_X_SERVER(x);
  const std::string title = "vkpt-window-input";
  Presenter p(title, 160, 120, "", true);
  glfwSetInputMode(p.Window(), GLFW_STICKY_KEYS, GLFW_TRUE);  // a press is seen even if released since
  glfwSetInputMode(p.Window(), GLFW_STICKY_MOUSE_BUTTONS, GLFW_TRUE);
  ShowAndRead(p, x, title, Halves(160, 120), {160, 120}, [](uint32_t x, uint32_t y) { return HalvesAt(x, y, 160); });

  ASSERT_TRUE(x.SendKeys(title, {"Escape"}));
  bool pressed = false;
  for (int i = 0; i < 300 && !pressed; ++i) {
    Pump(1);
    pressed = glfwGetKey(p.Window(), GLFW_KEY_ESCAPE) == GLFW_PRESS;
  }
  EXPECT_TRUE(pressed) << "Escape never reached the window";

  ASSERT_TRUE(x.MouseDrag(title, 20, 20, 120, 80));
  bool clicked = false;
  double cx = 0.0, cy = 0.0;
  for (int i = 0; i < 300 && !(clicked && cx == 120.0 && cy == 80.0); ++i) {
    Pump(1);
    clicked = clicked || glfwGetMouseButton(p.Window(), GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    glfwGetCursorPos(p.Window(), &cx, &cy);
  }
  EXPECT_TRUE(clicked) << "the drag's button never reached the window";
  EXPECT_EQ(cx, 120.0);
  EXPECT_EQ(cy, 80.0);
  p.Show(Halves(160, 120), 160, 120);  // ImGui's GLFW callbacks saw it all too, without complaint
  EXPECT_EQ(p.ValidationMessages(), 0u);
}

// The letterbox rectangle (window/blit.h) without a window: the whole framebuffer for the
// same shape, bars on two sides otherwise, centred, rounded to the nearest pixel.
TEST(WindowFit, KeepsTheAspectRatioCentred) {
  const auto fit = [](uint32_t sw, uint32_t sh, uint32_t dw, uint32_t dh) {
    const PixelRect r = FitRect({sw, sh}, {dw, dh});
    return std::vector<int32_t>{r.x0, r.y0, r.x1, r.y1};
  };
  EXPECT_EQ(fit(160, 120, 160, 120), (std::vector<int32_t>{0, 0, 160, 120}));
  EXPECT_EQ(fit(160, 120, 320, 240), (std::vector<int32_t>{0, 0, 320, 240}));
  EXPECT_EQ(fit(160, 120, 240, 90), (std::vector<int32_t>{60, 0, 180, 90}));  // pillarbox
  EXPECT_EQ(fit(240, 90, 160, 120), (std::vector<int32_t>{0, 30, 160, 90}));  // letterbox
  EXPECT_EQ(fit(100, 100, 101, 50), (std::vector<int32_t>{25, 0, 75, 50}));
  EXPECT_EQ(fit(3, 1, 100, 100), (std::vector<int32_t>{0, 33, 100, 66}));      // 33.3 rows: 33
  EXPECT_EQ(fit(10000, 1, 100, 100), (std::vector<int32_t>{0, 49, 100, 50}));  // at least one row
}

}  // namespace
}  // namespace vkpt::internal

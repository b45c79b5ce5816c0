// vkpt --interactive as a user meets it, under Xvfb: the window shows the batch render's
// picture once it has the same samples, a drag moves the view, P saves the render so far
// and prints a command whose render is that file bit for bit, Escape and Ctrl-C quit
// with 0; without a display it fails at once; batch-only options are refused; the
// printed command keeps every other option and quotes what a shell would split.
#include <signal.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "app/interactive.h"
#include "test_util.h"
#include "viewer/display_pixels.h"
#include "vkpt/vkpt.h"
#include "x_server.h"

namespace vkpt::internal {
namespace {

const std::string kTitle = "vkpt: cornell.gltf";

std::vector<std::string> ViewerArgs() {
  return {"--scene",
          test::SourcePath("scenes/cornell.gltf"),
          "--interactive",
          "--backend",
          "cpu",
          "--width",
          "160",
          "--height",
          "120",
          "--spp",
          "8",
          "--seed",
          "3"};
}

// The overlay's title bar, collapsed, stays above this row.
constexpr size_t kBelowOverlay = 32;

// The largest difference of any channel between the screen and `rgba` from row `first`
// down, or 256 when the sizes differ.
int LargestDifference(const std::vector<uint8_t>& rgb, const std::vector<uint8_t>& rgba, size_t width = 160,
                      size_t first = kBelowOverlay) {
  if (rgb.size() / 3 != rgba.size() / 4 || rgb.empty()) return 256;
  int largest = 0;
  for (size_t i = first * width; i < rgb.size() / 3; ++i)
    for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(int(rgb[i * 3 + c]) - int(rgba[i * 4 + c])));
  return largest;
}

// Pixels of the top-left 140 × 90 that differ between two screens by more than 16.
size_t ChangedInPanelArea(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  size_t changed = 0;
  for (size_t y = 0; y < 90; ++y)
    for (size_t x = 0; x < 140; ++x)
      for (int c = 0; c < 3; ++c)
        if (std::abs(int(a[(y * 160 + x) * 3 + c]) - int(b[(y * 160 + x) * 3 + c])) > 16) {
          ++changed;
          break;
        }
  return changed;
}

// Polls the window's pixels until `done` says so, for at most `seconds`; the last read.
std::vector<uint8_t> WaitForPicture(const test::XServer& x, double seconds,
                                    const std::function<bool(const std::vector<uint8_t>&)>& done) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds * test::kTimeScale);
  std::vector<uint8_t> rgb;
  while (std::chrono::steady_clock::now() < end) {
    uint32_t w = 0, h = 0;
    rgb = x.ReadWindowRGB(kTitle, w, h);
    if (!rgb.empty() && done(rgb)) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  return rgb;
}

TEST(Viewer, ShowsTheBatchPictureMovesSavesAndQuits) {
  test::XServer x(320, 240);
  VKPT_REQUIRE_X_SERVER(x);
  const test::TempFolder dir("viewer");
  // What the batch render shows at the same samples: the window's picture at rest.
  vkpt::SceneOptions cpu;
  cpu.backend = vkpt::Backend::Cpu;
  vkpt::RenderOptions render;
  render.width = 160, render.height = 120, render.spp = 8, render.seed = 3;
  const vkpt::RenderResult batch = vkpt::Scene(test::SourcePath("scenes/cornell.gltf"), cpu).Render({}, render);
  const std::vector<uint8_t> expected = DisplayPixels(batch.image, {View::kNeutral, 0.0f});

  test::ProcessResult run;
  std::thread viewer([&] { run = test::RunVkpt(ViewerArgs(), 120.0, dir.path); });
  const std::vector<uint8_t> rested =
      WaitForPicture(x, 60.0, [&](const std::vector<uint8_t>& rgb) { return LargestDifference(rgb, expected) <= 1; });
  EXPECT_LE(LargestDifference(rested, expected), 1) << "the window never showed the batch render's picture";

  // The overlay sits collapsed in the top-left corner; a click on its arrow opens it.
  EXPECT_GT(ChangedInPanelArea(rested, std::vector<uint8_t>(rested.size(), 0)), 0u);
  std::vector<uint8_t> batchRgb;
  for (size_t i = 0; i < expected.size(); i += 4)
    batchRgb.insert(batchRgb.end(), {expected[i], expected[i + 1], expected[i + 2]});
  const size_t collapsed = ChangedInPanelArea(rested, batchRgb);
  EXPECT_GT(collapsed, 100u) << "no overlay's title bar over the picture";
  EXPECT_TRUE(x.MouseClick(kTitle, 16, 17));
  const std::vector<uint8_t> opened = WaitForPicture(
      x, 10.0, [&](const std::vector<uint8_t>& rgb) { return ChangedInPanelArea(rgb, batchRgb) > 3 * collapsed; });
  EXPECT_GT(ChangedInPanelArea(opened, batchRgb), 3 * collapsed) << "the overlay did not open";
  EXPECT_TRUE(x.MouseClick(kTitle, 16, 17));  // and closed again

  // A drag turns the view: the picture leaves the batch render's.
  EXPECT_TRUE(x.MouseDrag(kTitle, 60, 70, 100, 80));
  const std::vector<uint8_t> turned =
      WaitForPicture(x, 30.0, [&](const std::vector<uint8_t>& rgb) { return LargestDifference(rgb, expected) > 64; });
  EXPECT_GT(LargestDifference(turned, expected), 64) << "a drag did not move the camera";
  std::this_thread::sleep_for(std::chrono::seconds(2));  // at rest, full size again
  EXPECT_TRUE(x.SendKeys(kTitle, {"p"}));
  std::this_thread::sleep_for(std::chrono::seconds(1));
  EXPECT_TRUE(x.SendKeys(kTitle, {"Escape"}));
  viewer.join();
  ASSERT_TRUE(run.ExitedWith(0)) << run.Describe();
  EXPECT_EQ(run.err.find("validation"), std::string::npos) << run.err;  // the window's device, validated

  // P's files, and its command: rendered again, the same EXR byte for byte.
  const size_t saved = run.out.find("vkpt: saved cornell.png and cornell.exr at ");
  ASSERT_NE(saved, std::string::npos) << run.out;
  const size_t command = run.out.find("vkpt --scene ", saved);
  ASSERT_NE(command, std::string::npos) << run.out;
  const std::string line = run.out.substr(command, run.out.find('\n', command) - command);
  EXPECT_NE(line.find(" --look-from "), std::string::npos) << line;
  EXPECT_EQ(line.find("--interactive"), std::string::npos) << line;
  const test::ProcessResult again =
      test::RunProgram("/bin/sh", {"-c", "\"$VKPT\"" + line.substr(4) + " --out batch.exr"}, 120.0, dir.path,
                       {std::string("VKPT=") + VKPT_BINARY});
  ASSERT_TRUE(again.ExitedWith(0)) << again.Describe();
  EXPECT_EQ(test::ReadFile(dir / "batch.exr"), test::ReadFile(dir / "cornell.exr"));
}

TEST(Viewer, CtrlCQuitsWithZero) {
  test::XServer x(320, 240);
  VKPT_REQUIRE_X_SERVER(x);
  const test::TempFolder dir("viewer-sigint");
  const test::ProcessResult r =
      test::RunVkpt(ViewerArgs(), 120.0, dir.path, {}, {}, {"vkpt: drag to orbit", {SIGINT}, 0.0, 1.0});
  EXPECT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_TRUE(dir.Listing().empty());  // nothing saved unasked
}

TEST(Viewer, WithoutADisplayFailsAtOnce) {
  const test::ScopedEnv display("DISPLAY", std::nullopt), wayland("WAYLAND_DISPLAY", std::nullopt);
  const test::ProcessResult r = test::RunVkpt(ViewerArgs(), 60.0);
  EXPECT_TRUE(r.ExitedWith(2)) << r.Describe();
  EXPECT_NE(r.err.find("DISPLAY"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("WAYLAND_DISPLAY"), std::string::npos) << r.err;
  EXPECT_LT(r.seconds, 5.0 * test::kTimeScale);  // before loading anything
}

TEST(Viewer, RefusesWhatOnlyABatchRenderDoes) {
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{"--frames", "0:2"}, {"--time", "5"}, {"--aov", "depth"}, {"--compare"}}) {
    std::vector<std::string> args = ViewerArgs();
    args.insert(args.end(), extra.begin(), extra.end());
    const test::ProcessResult r = test::RunVkpt(args, 60.0);
    EXPECT_TRUE(r.ExitedWith(2)) << extra[0] << ": " << r.Describe();
    EXPECT_NE(r.err.find("--interactive shows one view"), std::string::npos) << r.err;
  }
}

// What the viewer shows of `o` before anything is changed.
ViewedFrame Unchanged(const Options& o, uint32_t spp) {
  ViewedFrame f{std::nullopt, spp, 64, 48, {}};
  f.settings.display = o.Display();
  f.settings.maxDepth = o.api.render.maxDepth;
  f.settings.denoise = o.api.render.denoise;
  return f;
}

TEST(Viewer, TheBatchCommandReplacesTheViewAndKeepsTheRest) {
  std::vector<const char*> argv = {"vkpt",   "--scene", "my scene.gltf", "--interactive", "--fov",
                                   "30",     "--view",  "agx",           "--width",       "64",
                                   "--seed", "9",       "--out",         "it's.png"};
  const Options o = ParseOptions(int(argv.size()), argv.data());
  ViewedFrame moved = Unchanged(o, 24);
  moved.camera = vkpt::Camera{};
  moved.camera->lookFrom = std::array<float, 3>{0.1f, 2.0f, -3.5f};
  moved.camera->lookAt = std::array<float, 3>{0.0f, 0.0f, 0.0f};
  moved.camera->up = std::array<float, 3>{0.0f, 1.0f, 0.0f};
  moved.camera->fovDegrees = 0.1 + 0.2;
  EXPECT_EQ(BatchCommand(o, moved),
            "vkpt --scene 'my scene.gltf' --view agx --seed 9 --out 'it'\\''s.png' --width 64 --height 48 --spp 24 "
            "--look-from 0.100000001,2,-3.5 --look-at 0,0,0 --up 0,1,0 --fov 0.30000000000000004");
  EXPECT_EQ(BatchCommand(o, Unchanged(o, 5)),
            "vkpt --scene 'my scene.gltf' --fov 30 --view agx --seed 9 --out 'it'\\''s.png' --width 64 --height 48 "
            "--spp 5");
  // What the overlay changed replaces what was given, or joins it.
  ViewedFrame changed = Unchanged(o, 5);
  changed.settings.display = {View::kNeutral, 1.5f};
  changed.settings.maxDepth = 4;
  changed.settings.denoise = true;
  changed.settings.aov = "depth";
  EXPECT_EQ(BatchCommand(o, changed),
            "vkpt --scene 'my scene.gltf' --fov 30 --seed 9 --out 'it'\\''s.png' --width 64 --height 48 --spp 5 "
            "--view neutral --exposure 1.5 --max-depth 4 --denoise --aov depth");
}

}  // namespace
}  // namespace vkpt::internal

// The library API (vkpt/vkpt.h): renders of one loaded Scene equal the command line's,
// bit for bit; a camera change equals a fresh load with that camera; Scenes render on two
// threads at once as they do alone; every failure is a vkpt::Error naming its cause; the
// devices listed are the command line's.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "api_test_util.h"
#include "image/image.h"
#include "test_util.h"

#include "vkpt/vkpt.h"

namespace vkpt::internal {
namespace {

const std::string kCornell = test::Cornell();

vkpt::Camera Orbit(double degrees) {
  vkpt::Camera c;
  c.orbitDegrees = degrees;
  return c;
}

// The RGB floats of the command line's render of `args` (a .pfm).
std::vector<float> CliRender(std::vector<std::string> args, const std::string& out) {
  args.insert(args.end(),
              {"--scene", kCornell, "--width", "24", "--height", "16", "--spp", "4", "--chunk", "4", "--out", out});
  const test::ProcessResult r = test::RunVkpt(args);
  EXPECT_TRUE(r.ExitedWith(0)) << r.Describe();
  const auto image = ReadPfm(out);  // Image, the internal one
  std::vector<float> rgb;
  for (const glm::vec3& p : image.pixels) rgb.insert(rgb.end(), {p.r, p.g, p.b});
  return rgb;
}

TEST(Api, RendersOfOneSceneEqualTheCommandLines) {
  VKPT_SKIP_UNDER_ADDRESS_SANITIZER("eight command-line renders against the library's, 20 s");
  const std::string dir = test::FreshTempDirectory("api-cli");
  for (const char* backend : {"cpu", "vulkan"}) {
    vkpt::SceneOptions options;
    options.backend = std::string(backend) == "cpu" ? vkpt::Backend::Cpu : vkpt::Backend::Vulkan;
    vkpt::Scene scene(kCornell, options);
    vkpt::RenderOptions depth = test::SmallRender(7);
    depth.aovs = {"depth"};
    const vkpt::RenderResult a = scene.Render(vkpt::Camera{}, depth);
    const vkpt::RenderResult b = scene.Render(Orbit(30.0), test::SmallRender(3));
    EXPECT_EQ(a.image.data, CliRender({"--backend", backend, "--seed", "7", "--aov", "depth"}, dir + "/a.pfm"))
        << backend;
    EXPECT_EQ(b.image.data, CliRender({"--backend", backend, "--seed", "3", "--orbit", "30"}, dir + "/b.pfm"))
        << backend;
    // The CLI's depth PFM repeats the one channel in R, G and B.
    const auto cliDepth = ReadPfm(dir + "/a.depth.pfm");
    const vkpt::Image& apiDepth = a.aovs.at("depth");
    ASSERT_EQ(apiDepth.channels, 1u);
    ASSERT_EQ(apiDepth.data.size(), cliDepth.pixels.size());
    for (size_t i = 0; i < apiDepth.data.size(); ++i) ASSERT_EQ(apiDepth.data[i], cliDepth.pixels[i].r) << i;
    EXPECT_NE(a.image.data, b.image.data);
    EXPECT_EQ(scene.Device() == "cpu", std::string(backend) == "cpu");
  }
}

TEST(Api, CameraChangeEqualsAFreshLoad) {
  vkpt::SceneOptions cpu;
  cpu.backend = vkpt::Backend::Cpu;
  vkpt::Scene scene(kCornell, cpu);
  EXPECT_EQ(scene.CameraCount(), 1u);  // known before the first render
  scene.Render(vkpt::Camera{}, test::SmallRender());
  vkpt::Camera moved;
  moved.lookFrom = {{278.0f, 400.0f, -600.0f}};
  moved.fovDegrees = 50.0;
  const vkpt::RenderResult after = scene.Render(moved, test::SmallRender());
  EXPECT_EQ(after.image.data, vkpt::Scene(kCornell, cpu).Render(moved, test::SmallRender()).image.data);
  EXPECT_EQ(after.image.width, 24u);
  EXPECT_EQ(after.image.height, 16u);
  EXPECT_EQ(after.image.channels, 3u);
  EXPECT_EQ(after.image.data.size(), 24u * 16u * 3u);
  EXPECT_EQ(after.spp, 4u);
  EXPECT_EQ(scene.CameraCount(), 1u);
}

// The Cornell box's camera node (at (278, 273, −800), turned 180° about +Y) as a matrix
// renders the file's camera; a matrix that places no camera is refused naming the file.
TEST(Api, CameraMatrixPlacesTheLens) {
  vkpt::SceneOptions cpu;
  cpu.backend = vkpt::Backend::Cpu;
  vkpt::Scene scene(kCornell, cpu);
  vkpt::Camera placed;
  placed.matrix = {{-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 278, 273, -800, 1}};
  EXPECT_EQ(scene.Render(placed, test::SmallRender()).image.data,
            scene.Render(vkpt::Camera{}, test::SmallRender()).image.data);
  placed.matrix->at(10) = 0.0f;
  try {
    scene.Render(placed, test::SmallRender());
    ADD_FAILURE() << "a singular camera matrix was accepted";
  } catch (const vkpt::Error& e) {
    EXPECT_EQ(std::string(e.what()),
              kCornell + ": the camera matrix is singular: its −Z and +Y axes must be independent");
  }
}

// Two Scenes (one per thread, each with its device) render at once what they render alone.
TEST(Api, ScenesOnTwoThreadsRenderAsAlone) {
  vkpt::SceneOptions vulkan;
  vulkan.backend = vkpt::Backend::Vulkan;
  vulkan.validation = true;
  vkpt::Scene a(kCornell, vulkan), b(kCornell, vulkan);
  const std::vector<float> aloneA = a.Render(vkpt::Camera{}, test::SmallRender(1)).image.data;
  const std::vector<float> aloneB = b.Render(Orbit(45.0), test::SmallRender(2)).image.data;
  std::vector<float> together[2];
  std::thread ta([&] { together[0] = a.Render(vkpt::Camera{}, test::SmallRender(1)).image.data; });
  std::thread tb([&] { together[1] = b.Render(Orbit(45.0), test::SmallRender(2)).image.data; });
  ta.join();
  tb.join();
  EXPECT_EQ(together[0], aloneA);
  EXPECT_EQ(together[1], aloneB);
}

TEST(Api, FailuresAreErrorsNamingTheirCause) {
  auto message = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const vkpt::Error& e) {
      return e.what();
    }
    return "(no error)";
  };
  vkpt::SceneOptions cpu;
  cpu.backend = vkpt::Backend::Cpu;
  const std::string missing = test::TempPath("no-such.glb");
  EXPECT_NE(message([&] { vkpt::Scene(missing, cpu); }).find(missing), std::string::npos);
  vkpt::Scene scene(kCornell, cpu);
  vkpt::RenderOptions bad = test::SmallRender();
  bad.aovs = {"depht"};
  EXPECT_EQ(message([&] { scene.Render(vkpt::Camera{}, bad); }),
            "unknown AOV \"depht\" (albedo, normal, depth, position, variance, spp, heatmap, object_id, material_id, "
            "instance_id or all)");
  vkpt::Camera third;
  third.index = 3;
  // The message names no command-line option.
  EXPECT_EQ(message([&] { scene.Render(third, test::SmallRender()); }),
            kCornell + ": camera 3 is out of range; the scene has 1 camera(s)");
  vkpt::SceneOptions tiny = cpu;
  tiny.maxMemory = 1024;
  // The engine's messages name the API's settings, not the command line's options.
  const std::string tooBig = message([&] { vkpt::Scene(kCornell, tiny); });
  EXPECT_NE(tooBig.find("more than SceneOptions::maxMemory 1 KiB allows (raise SceneOptions::maxMemory"),
            std::string::npos)
      << tooBig;
  vkpt::SceneOptions ninth;
  ninth.backend = vkpt::Backend::Vulkan;
  ninth.device = "9";
  EXPECT_EQ(message([&] { vkpt::Scene(kCornell, ninth); }),
            "SceneOptions::device 9: there are only 1 Vulkan device(s) (`vkpt --list-devices` lists them)");
  // The scene still renders after a failed render.
  EXPECT_EQ(scene.Render(vkpt::Camera{}, test::SmallRender()).image.data.size(), 24u * 16u * 3u);
}

// A camera's aspect ratio far from 1 asks for a side beyond any image: refused, naming the
// ratio, unless both sides are given; a side that rounds to nothing is one pixel.
TEST(Api, AnAspectRatioFarFromOneNeedsBothSides) {
  struct Case {
    double ratio;
    bool tall;          // the width given, the height following
    const char* shown;  // the message's start
  };
  for (const Case& c : {Case{1.19e-7, true, "aspectRatio 1.19e-07 asks for a 24 × 2016806"},
                        Case{1e-17, true, "aspectRatio 1e-17 asks for a 24 × 24000000"},
                        Case{1e7, false, "aspectRatio 1e+07 asks for a 160000000 × 16 image, beyond 16384 pixels"}}) {
    const test::TempFolder folder("api-aspect");
    const std::string path = test::WriteCornell(
        folder, "aspect.gltf", [&](nlohmann::json& f) { f["cameras"][0]["perspective"]["aspectRatio"] = c.ratio; });
    vkpt::Scene scene = test::Open(path, vkpt::Backend::Cpu);
    vkpt::RenderOptions oneSide = test::SmallRender();
    (c.tall ? oneSide.height : oneSide.width).reset();
    try {
      scene.Render({}, oneSide);
      ADD_FAILURE() << c.ratio << " rendered";
    } catch (const vkpt::Error& e) {
      EXPECT_NE(std::string(e.what()).find(c.shown), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
    EXPECT_EQ(scene.Render({}, test::SmallRender()).image.height, 16u) << c.ratio;
    if (c.tall) continue;
    vkpt::RenderOptions flat = test::SmallRender();
    flat.height.reset();
    EXPECT_EQ(scene.Render({}, flat).image.height, 1u);  // 24 / 1e7 rounds to 0
  }
}

TEST(Api, DenoisedImageKeepsTheRawOne) {
  vkpt::SceneOptions cpu;
  cpu.backend = vkpt::Backend::Cpu;
  vkpt::RenderOptions o = test::SmallRender();
  o.denoise = true;
  o.aovs = {"all"};
  const vkpt::RenderResult r = vkpt::Scene(kCornell, cpu).Render(vkpt::Camera{}, o);
  ASSERT_TRUE(r.raw.has_value());
  EXPECT_NE(r.raw->data, r.image.data);
  EXPECT_EQ(r.aovs.size(), 10u);
  EXPECT_EQ(r.aovs.at("normal").channels, 3u);
  EXPECT_EQ(r.aovs.at("normal").channelNames, (std::vector<std::string>{"X", "Y", "Z"}));
}

// A cancel ends the render between passes; the image is the render of the samples taken.
TEST(Api, CancelEndsTheRenderWithTheSamplesTaken) {
  vkpt::SceneOptions cpu;
  cpu.backend = vkpt::Backend::Cpu;
  vkpt::Scene scene(kCornell, cpu);
  vkpt::RenderOptions o = test::SmallRender();
  o.spp = 256;
  int asked = 0;
  o.cancel = [&asked] { return ++asked == 3; };
  const vkpt::RenderResult cancelled = scene.Render(vkpt::Camera{}, o);
  EXPECT_EQ(asked, 3);
  EXPECT_EQ(cancelled.stoppedBy, "cancelled");
  ASSERT_GT(cancelled.spp, 0u);
  ASSERT_LT(cancelled.spp, 256u);
  vkpt::RenderOptions fixed = test::SmallRender();
  fixed.spp = cancelled.spp;
  const vkpt::RenderResult whole = scene.Render(vkpt::Camera{}, fixed);
  EXPECT_EQ(whole.stoppedBy, "spp");
  EXPECT_EQ(cancelled.image.data, whole.image.data);
}

// Devices() lists what --list-devices prints, and a Scene opened on a device by its index
// renders there (lavapipe in CI: one device, a CPU, with a compute queue).
TEST(Api, DevicesAreTheCommandLinesList) {
  const std::vector<vkpt::Device> devices = vkpt::Devices();
  ASSERT_FALSE(devices.empty()) << "lavapipe (mesa-vulkan-drivers) should be installed";
  const test::ProcessResult r = test::RunVkpt({"--list-devices"});
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  std::string listed;
  for (size_t i = 0; i < devices.size(); ++i) {
    const vkpt::Device& d = devices[i];
    EXPECT_EQ(d.index, i);
    EXPECT_GE(d.apiMajor * 10 + d.apiMinor, 12u) << d.name;
    listed += std::to_string(d.index) + ": " + d.name + " (" + d.type + ", Vulkan " + std::to_string(d.apiMajor) + "." +
              std::to_string(d.apiMinor) + ")" + (d.compute ? "" : " [no compute queue]") + "\n";
  }
  EXPECT_EQ(r.out, listed);
  vkpt::SceneOptions options;
  options.backend = vkpt::Backend::Vulkan;
  options.device = std::to_string(devices.back().index);
  EXPECT_EQ(vkpt::Scene(kCornell, options).Device(), devices.back().name);
}

}  // namespace
}  // namespace vkpt::internal

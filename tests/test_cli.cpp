// The vkpt command line, run as a subprocess: help and version, usage errors (exit 2),
// scene and I/O errors (exit 1), output formats, determinism and the verbose report.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "gltf_builder.h"
#include "image/image.h"
#include "png_writer.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

namespace fs = std::filesystem;
using test::DirectoryListing;
using test::ProcessResult;
using test::ReadFile;
using test::RunVkpt;
using test::SourcePath;
using test::TempPath;

const std::string kCornell = SourcePath("scenes/cornell.gltf");

// Files in `dir` whose name starts with `prefix` (to catch leftover temporaries).
std::vector<std::string> FilesStartingWith(const std::string& dir, const std::string& prefix) {
  std::vector<std::string> found;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec))
    if (e.path().filename().string().rfind(prefix, 0) == 0) found.push_back(e.path().string());
  return found;
}

// A small, fast render of the Cornell box into `out`, on the CPU backend (always
// available; these tests are about the command line, not the device).
ProcessResult RenderCornell(const std::string& out, std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"--scene", kCornell, "--backend", "cpu", "--width", "24", "--height", "24",
                                   "--spp",   "2",      "--out",     out};
  args.insert(args.end(), extra.begin(), extra.end());
  return RunVkpt(args, 60.0);
}

// ---------------------------------------------------------------------------------------
// Help, version, usage errors

TEST(Cli, HelpListsEveryOption) {
  for (const char* flag : {"--help", "-h"}) {
    ProcessResult r = RunVkpt({flag});
    ASSERT_TRUE(r.ExitedWith(0)) << flag << ": " << r.Describe();
    EXPECT_TRUE(r.err.empty()) << r.err;
    EXPECT_NE(r.out.find("usage:"), std::string::npos) << r.out;
    for (const char* opt : {"--scene",        "--out",         "--width",      "--height",       "--spp",
                            "--seed",         "--max-depth",   "--rr-depth",   "--backend",      "--device",
                            "--list-devices", "--validation",  "--batch",      "--threads",      "--compare",
                            "--diff",         "--camera",      "--background", "--exposure",     "--leaf-size",
                            "--splits",       "--stats",       "-v",           "--verbose",      "--help",
                            "--version",      "--texture-lod", "--time",       "--noise-target", "--adaptive",
                            "--no-adaptive",  "--checkpoint",  "--look-from",  "--look-at",      "--up",
                            "--fov",          "--orbit",       "--view"})
      EXPECT_NE(r.out.find(opt), std::string::npos) << flag << " output does not mention " << opt;
    EXPECT_NE(r.out.find(".png"), std::string::npos);
    EXPECT_NE(r.out.find(".pfm"), std::string::npos);
    EXPECT_NE(r.out.find(".exr"), std::string::npos);
  }
}

TEST(Cli, HelpWinsOverMissingScene) {
  ProcessResult r = RunVkpt({"--spp", "4", "--help"});
  EXPECT_TRUE(r.ExitedWith(0)) << r.Describe();
}

TEST(Cli, Version) {
  ProcessResult r = RunVkpt({"--version"});
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_TRUE(std::regex_search(r.out, std::regex("^vkpt [0-9]+\\.[0-9]+\\.[0-9]+"))) << r.out;
}

TEST(Cli, NoArgumentsIsUsageError) {
  ProcessResult r = RunVkpt({});
  EXPECT_TRUE(r.ExitedWith(2)) << r.Describe();
  EXPECT_NE(r.err.find("usage error"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--scene"), std::string::npos) << r.err;
}

TEST(Cli, UnknownOptionIsUsageError) {
  ProcessResult r = RunVkpt({"--scene", kCornell, "--frobnicate", "3"});
  EXPECT_TRUE(r.ExitedWith(2)) << r.Describe();
  EXPECT_EQ(r.err.rfind("vkpt: usage error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("--frobnicate"), std::string::npos) << r.err;
}

TEST(Cli, BadValuesAreUsageErrors) {
  const std::string out = TempPath("cli-bad-values.png");
  const std::vector<std::vector<std::string>> cases = {
      {"--spp", "0"},
      {"--spp", "abc"},
      {"--spp", "4x"},
      {"--spp", ""},
      {"--width", "-3"},
      {"--width", "0"},
      {"--height", "99999"},
      {"--threads", "1025"},
      {"--backend", "foo"},
      {"--background", "1,2"},
      {"--background", "1,2,3,4"},
      {"--background", "-1"},
      {"--background", "a"},
      {"--leaf-size", "16"},
      {"--exposure", "nan"},
      {"--view", "filmic"},
      {"--seed", "-1"},
      {"--max-depth", "1.5"},
      {"--camera", "x"},
      {"--spp"},
      {"--batch", "1073741825"},
      {"--device", ""},
      {"--rr-depth", "1025"},
      {"--splits", "sbvh"},
      {"--texture-lod", "auto"},
      {"--look-from", "1,2"},
      {"--look-at", "1,2,3,4"},
      {"--up", "0,x,1"},
      {"--look-from", "1e10,0,0"},
      {"--fov", "0"},
      {"--fov", "180"},
      {"--orbit", "inf"},
  };
  for (const std::vector<std::string>& c : cases) {
    std::vector<std::string> args = {"--scene", kCornell, "--out", out};
    args.insert(args.end(), c.begin(), c.end());
    ProcessResult r = RunVkpt(args, 30.0);
    std::string what = ::testing::PrintToString(c);
    EXPECT_TRUE(r.ExitedWith(2)) << what << ": " << r.Describe();
    EXPECT_EQ(r.err.rfind("vkpt: usage error: ", 0), 0u) << what << ": " << r.err;
    EXPECT_NE(r.err.find(c[0]), std::string::npos) << what << ": the message does not name the option: " << r.err;
    EXPECT_FALSE(fs::exists(out)) << what;
    std::remove(out.c_str());
  }
}

TEST(Cli, InlineOptionValuesAreAccepted) {
  const std::string out = TempPath("cli-inline.pfm");
  ProcessResult r = RunVkpt({"--scene=" + kCornell, "--width=8", "--height=6", "--spp=1", "--out=" + out}, 60.0);
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  Image img = ReadPfm(out);
  EXPECT_EQ(img.width, 8u);
  EXPECT_EQ(img.height, 6u);
  std::remove(out.c_str());
}

// ---------------------------------------------------------------------------------------
// Errors (exit 1)

TEST(Cli, UnsupportedOutputExtension) {
  const std::string out = TempPath("cli-out.jpg");
  std::remove(out.c_str());
  ProcessResult r = RenderCornell(out);
  EXPECT_TRUE(r.ExitedWith(1) || r.ExitedWith(2)) << r.Describe();
  for (const char* ext : {".png", ".pfm", ".exr"}) EXPECT_NE(r.err.find(ext), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(out), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(FilesStartingWith("/tmp", fs::path(out).filename().string()).empty());
}

TEST(Cli, UnsupportedOutputExtensionFailsBeforeRendering) {
  // A render that would take far longer than the timeout: the extension must be checked
  // before it starts.
  const std::string out = TempPath("cli-early.tga");
  ProcessResult r = RunVkpt({"--scene", kCornell, "--backend", "cpu", "--width", "4096", "--height", "4096", "--spp",
                             "1000000", "--out", out},
                            20.0);
  EXPECT_FALSE(r.timedOut) << "the output format was not checked before rendering";
  EXPECT_TRUE(r.ExitedWith(1) || r.ExitedWith(2)) << r.Describe();
  EXPECT_NE(r.err.find(".pfm"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, MissingSceneFile) {
  const std::string scene = TempPath("cli-no-such-scene.gltf");
  const std::string out = TempPath("cli-missing-scene.png");
  std::remove(scene.c_str());
  ProcessResult r = RunVkpt({"--scene", scene, "--out", out});
  EXPECT_TRUE(r.ExitedWith(1)) << r.Describe();
  EXPECT_EQ(r.err.rfind("vkpt: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(scene), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, CameraIndexOutOfRange) {
  const std::string out = TempPath("cli-camera5.png");
  ProcessResult r = RenderCornell(out, {"--camera", "5"});
  EXPECT_TRUE(r.ExitedWith(1)) << r.Describe();
  EXPECT_EQ(r.err.rfind("vkpt: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("out of range"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(kCornell), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, CameraZeroIsTheFileCamera) {
  const std::string a = TempPath("cli-cam-default.pfm"), b = TempPath("cli-cam-0.pfm");
  ASSERT_TRUE(RenderCornell(a).ExitedWith(0));
  ASSERT_TRUE(RenderCornell(b, {"--camera", "0"}).ExitedWith(0));
  EXPECT_EQ(ReadFile(a), ReadFile(b));
  std::remove(a.c_str());
  std::remove(b.c_str());
}

// The Cornell box's camera (at (278, 273, −800), looking along +Z, up +Y) given again by
// --look-from, --look-at and --up renders the same image, within the rounding of its
// view recomputed from the two points; turned by --orbit 360 too. Turned by 90° about
// the box's centre (278, 273, 279.6) it stands at its −X side, looking along +X.
TEST(Cli, LookAtAndOrbitMoveTheCamera) {
  const std::string a = TempPath("cli-look-file.pfm"), b = TempPath("cli-look-at.pfm"), c = TempPath("cli-orbit.pfm");
  ASSERT_TRUE(RenderCornell(a).ExitedWith(0));
  ProcessResult same = RenderCornell(b, {"--look-from", "278,273,-800", "--look-at", "278,273,0", "--up", "0,1,0"});
  ASSERT_TRUE(same.ExitedWith(0)) << same.Describe();
  ProcessResult turned = RenderCornell(c, {"--orbit", "360", "-v"});
  ASSERT_TRUE(turned.ExitedWith(0)) << turned.Describe();
  const Image ia = ReadPfm(a), ib = ReadPfm(b), ic = ReadPfm(c);
  ASSERT_EQ(ia.pixels.size(), ib.pixels.size());
  int off = 0, offOrbit = 0;
  for (size_t i = 0; i < ia.pixels.size(); ++i) {
    off += glm::any(glm::greaterThan(glm::abs(ia.pixels[i] - ib.pixels[i]), glm::vec3(1e-3f)));
    offOrbit += glm::any(glm::greaterThan(glm::abs(ia.pixels[i] - ic.pixels[i]), glm::vec3(1e-3f)));
  }
  std::printf("--look-from/--look-at: %d, --orbit 360: %d of %zu pixels off by more than 1e-3 (<= 2 %%)\n", off,
              offOrbit, ia.pixels.size());
  EXPECT_LE(off, int(ia.pixels.size() / 50));
  EXPECT_LE(offOrbit, int(ia.pixels.size() / 50));
  ProcessResult quarter = RenderCornell(c, {"--orbit", "90", "-v"});
  ASSERT_TRUE(quarter.ExitedWith(0)) << quarter.Describe();
  EXPECT_TRUE(std::regex_search(quarter.out, std::regex("turned by --orbit\" at \\(-801\\.[0-9]+, 273, 279\\.[0-9]+\\) "
                                                        "looking \\(1, [-0-9e.]+, [-0-9e.]+\\)")))
      << quarter.out;
  for (const std::string& f : {a, b, c}) std::remove(f.c_str());
}

// Where the camera cannot be placed, the error names the file and why, and nothing is
// written.
TEST(Cli, CameraThatCannotBePlacedIsAnError) {
  const std::string out = TempPath("cli-look-bad.png");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--look-from", "1,2,3", "--look-at", "1,2,3"}, "look-at point is where it stands"},
      {{"--look-from", "0,5,0", "--look-at", "0,0,0"}, "up direction lies along its view"},
      {{"--up", "0,0,2"}, "up direction lies along its view"}};
  for (const auto& [args, message] : cases) {
    ProcessResult r = RenderCornell(out, args);
    EXPECT_TRUE(r.ExitedWith(1)) << r.Describe();
    EXPECT_EQ(r.err.rfind(std::string("vkpt: error: ") + kCornell + ": ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

// --fov sets a perspective camera's field of view (-v shows it) and is an error for an
// orthographic one.
TEST(Cli, FovIsForPerspectiveCameras) {
  test::GltfBuilder b = test::TriangleModel();
  b.cameras.push_back(R"({"type":"orthographic","orthographic":{"xmag":1,"ymag":1,"znear":0.1,"zfar":10}})");
  b.Node(R"({"children":[1,2]})");
  b.Node(R"({"mesh":0})");
  b.Node(R"({"camera":0,"translation":[0.3,0.3,3]})");
  const test::TempFile file(b.Json());
  const std::string out = TempPath("cli-fov.png");
  ProcessResult ortho = RunVkpt({"--scene", file.path, "--spp", "1", "--width", "8", "--fov", "30", "--out", out});
  EXPECT_TRUE(ortho.ExitedWith(1)) << ortho.Describe();
  EXPECT_NE(ortho.err.find("a field of view is for perspective cameras, and camera 0 is orthographic"),
            std::string::npos)
      << ortho.err;
  EXPECT_FALSE(fs::exists(out));
  ProcessResult wide = RenderCornell(out, {"--fov", "75", "-v"});
  ASSERT_TRUE(wide.ExitedWith(0)) << wide.Describe();
  EXPECT_NE(wide.out.find("perspective yfov(deg) 75"), std::string::npos) << wide.out;
  std::remove(out.c_str());
}

// The suite pins lavapipe (VK_ICD_FILENAMES in tests/CMakeLists.txt), so Vulkan must
// work here: a render that fails for want of a device is a failure of this test. (How a
// missing device is reported is ExplicitVulkanWithoutDeviceNamesTheFix's business.)
TEST(Cli, VulkanBackendRendersOnLavapipe) {
  const std::string out = TempPath("cli-vulkan.png");
  std::remove(out.c_str());
  ProcessResult r = RunVkpt({"--scene", kCornell, "--backend", "vulkan", "--width", "24", "--height", "24", "--spp",
                             "2", "--out", out},
                            60.0);
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_TRUE(fs::exists(out));
  EXPECT_NE(r.out.find(": 24x24, 2 spp, vulkan: llvmpipe"), std::string::npos) << r.out;
  EXPECT_EQ(r.err.find("rendering on the CPU instead"), std::string::npos) << r.err;
  std::remove(out.c_str());
}

TEST(Cli, OutputInMissingDirectory) {
  const std::string dir = TempPath("cli-no-such-dir");
  fs::remove_all(dir);
  const std::string out = dir + "/image.png";
  ProcessResult r = RenderCornell(out);
  EXPECT_TRUE(r.ExitedWith(1)) << r.Describe();
  EXPECT_EQ(r.err.rfind("vkpt: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(out), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir)) << "the output directory was created";
  EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, OutputPathIsADirectoryLeavesNoTemporary) {
  const std::string parent = TempPath("cli-out-is-dir");
  fs::remove_all(parent);
  fs::create_directory(parent);
  const std::string out = parent + "/image.pfm";
  fs::create_directory(out);
  ProcessResult r = RenderCornell(out);
  EXPECT_TRUE(r.ExitedWith(1)) << r.Describe();
  EXPECT_EQ(r.err.rfind("vkpt: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(out), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_directory(out));
  EXPECT_TRUE(fs::is_empty(out));
  EXPECT_EQ(DirectoryListing(parent), std::vector<std::string>{"image.pfm"}) << "a temporary file was left behind";
  fs::remove_all(parent);
}

// ---------------------------------------------------------------------------------------
// Output

TEST(Cli, OutIsHonoured) {
  const std::string out = TempPath("cli-honoured.pfm");
  std::remove(out.c_str());
  ProcessResult r = RenderCornell(out);
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_TRUE(fs::exists(out));
  EXPECT_NE(r.out.find(out), std::string::npos) << "the summary line does not name the output: " << r.out;
  std::remove(out.c_str());
}

TEST(Cli, DefaultOutputIsSceneNamePngInWorkingDirectory) {
  const std::string dir = TempPath("cli-default-out");
  fs::remove_all(dir);
  fs::create_directory(dir);
  ProcessResult r = RunVkpt({"--scene", kCornell, "--width", "16", "--height", "16", "--spp", "1"}, 60.0, dir);
  EXPECT_TRUE(r.ExitedWith(0)) << r.Describe();
  const std::string png = ReadFile(dir + "/cornell.png");
  EXPECT_EQ(png.substr(0, 4), "\x89PNG");
  EXPECT_EQ(DirectoryListing(dir), std::vector<std::string>{"cornell.png"});
  fs::remove_all(dir);
}

TEST(Cli, OutputFormatsHaveTheRightMagic) {
  struct Case {
    const char* ext;
    std::string magic;
  };
  for (const Case& c : {Case{".png", "\x89PNG\r\n\x1a\n"}, Case{".pfm", "PF\n"},
                        Case{".exr", std::string("\x76\x2f\x31\x01", 4)}, Case{".PNG", "\x89PNG"}}) {
    const std::string out = TempPath(std::string("cli-format") + c.ext);
    std::remove(out.c_str());
    ProcessResult r = RenderCornell(out);
    ASSERT_TRUE(r.ExitedWith(0)) << c.ext << ": " << r.Describe();
    std::string bytes = ReadFile(out);
    EXPECT_GT(bytes.size(), 24u * 24u / 4) << c.ext;
    EXPECT_EQ(bytes.substr(0, c.magic.size()), c.magic) << c.ext;
    EXPECT_TRUE(FilesStartingWith("/tmp", fs::path(out).filename().string() + ".partial").empty()) << c.ext;
    std::remove(out.c_str());
  }
}

TEST(Cli, PfmHasRequestedSizeAndFiniteMeanNearSummary) {
  const std::string out = TempPath("cli-size.pfm");
  ProcessResult r = RunVkpt({"--scene", kCornell, "--width", "20", "--height", "10", "--spp", "2", "--out", out}, 60.0);
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  Image img = ReadPfm(out);
  EXPECT_EQ(img.width, 20u);
  EXPECT_EQ(img.height, 10u);
  double sum = 0.0;
  for (const glm::vec3& p : img.pixels) {
    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    sum += p.x + p.y + p.z;
  }
  EXPECT_GT(sum, 0.0) << "the Cornell box rendered black";
  EXPECT_NE(r.out.find("20x10"), std::string::npos) << r.out;
  std::remove(out.c_str());
}

TEST(Cli, MissingSideFollowsCameraAspectRatio) {
  VKPT_SKIP_UNDER_ADDRESS_SANITIZER("a dozen renders of image sizes, 10 s");
  // A triangle seen by a camera of aspectRatio 1.5 (as the corpus's Duck has).
  test::GltfBuilder b = test::TriangleModel();
  b.cameras.push_back(R"({"type":"perspective","perspective":{"yfov":0.8,"aspectRatio":1.5,"znear":0.1}})");
  b.Node(R"({"children":[1,2]})");
  b.Node(R"({"mesh":0})");
  b.Node(R"({"camera":0,"translation":[0.3,0.3,3]})");
  const test::TempFile file(b.Json());
  const std::string scene = file.path;
  const std::string out = TempPath("cli-aspect.pfm");
  struct Case {
    std::vector<std::string> size;
    uint32_t width, height;
  };
  for (const Case& c : {Case{{"--width", "12"}, 12, 8}, Case{{"--height", "10"}, 15, 10},
                        Case{{"--width", "7", "--height", "9"}, 7, 9}}) {
    std::vector<std::string> args = {"--scene", scene, "--spp", "1", "--out", out};
    args.insert(args.end(), c.size.begin(), c.size.end());
    ProcessResult r = RunVkpt(args, 60.0);
    ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
    Image img = ReadPfm(out);
    EXPECT_EQ(img.width, c.width) << ::testing::PrintToString(c.size);
    EXPECT_EQ(img.height, c.height) << ::testing::PrintToString(c.size);
    std::remove(out.c_str());
  }
}

// ---------------------------------------------------------------------------------------
// Determinism

TEST(Cli, SameSeedIsBitIdenticalAcrossThreadCounts) {
  const std::string a = TempPath("cli-det-t1.pfm"), b = TempPath("cli-det-t2.pfm"), c = TempPath("cli-det-seed.pfm");
  auto render = [](const std::string& out, const char* threads, const char* seed) {
    return RunVkpt({"--scene", kCornell, "--backend", "cpu", "--width", "48", "--height", "48", "--spp", "4", "--seed",
                    seed, "--threads", threads, "--out", out},
                   60.0);
  };
  ProcessResult ra = render(a, "1", "7");
  ProcessResult rb = render(b, "2", "7");
  ProcessResult rc = render(c, "2", "8");
  ASSERT_TRUE(ra.ExitedWith(0)) << ra.Describe();
  ASSERT_TRUE(rb.ExitedWith(0)) << rb.Describe();
  ASSERT_TRUE(rc.ExitedWith(0)) << rc.Describe();
  EXPECT_TRUE(std::regex_search(ra.out, std::regex("\\(1 threads?\\)"))) << ra.out;
  EXPECT_TRUE(std::regex_search(rb.out, std::regex("\\(2 threads?\\)"))) << rb.out;
  std::string ba = ReadFile(a), bb = ReadFile(b), bc = ReadFile(c);
  ASSERT_GT(ba.size(), 48u * 48u * 12u);
  EXPECT_TRUE(ba == bb) << "--seed 7 differs between --threads 1 and --threads 2";
  EXPECT_FALSE(ba == bc) << "--seed 7 and --seed 8 gave the same image";
  for (const std::string& p : {a, b, c}) std::remove(p.c_str());
}

bool HaveVulkanDevice() {
  ProcessResult r = RunVkpt({"--list-devices"}, 60.0);
  return r.ExitedWith(0) && std::regex_search(r.out, std::regex("^0: ", std::regex::multiline));
}

TEST(Cli, VulkanSameSeedIsBitIdentical) {
#if defined(VKPT_ADDRESS_SANITIZER)
  GTEST_SKIP() << "11 s under AddressSanitizer for the device's determinism; the plain build runs it";
#endif
  // The test environment pins lavapipe (tests/CMakeLists.txt): a missing device is a failure.
  ASSERT_TRUE(HaveVulkanDevice()) << "no Vulkan device: install mesa-vulkan-drivers";
  const std::string a = TempPath("cli-vk-a.pfm"), b = TempPath("cli-vk-b.pfm"), c = TempPath("cli-vk-c.pfm");
  auto render = [](const std::string& out, const char* seed) {
    return RunVkpt({"--scene", kCornell, "--backend", "vulkan", "--device", "0", "--width", "48", "--height", "48",
                    "--spp", "4", "--seed", seed, "--out", out},
                   120.0);
  };
  ProcessResult ra = render(a, "7"), rb = render(b, "7"), rc = render(c, "8");
  ASSERT_TRUE(ra.ExitedWith(0)) << ra.Describe();
  ASSERT_TRUE(rb.ExitedWith(0)) << rb.Describe();
  ASSERT_TRUE(rc.ExitedWith(0)) << rc.Describe();
  EXPECT_NE(ra.out.find("vulkan"), std::string::npos) << ra.out;
  std::string ba = ReadFile(a), bb = ReadFile(b), bc = ReadFile(c);
  ASSERT_GT(ba.size(), 48u * 48u * 12u);
  EXPECT_TRUE(ba == bb) << "two Vulkan renders with --seed 7 differ";
  EXPECT_FALSE(ba == bc) << "--seed 7 and --seed 8 gave the same image";
  Image img = ReadPfm(a);
  for (const glm::vec3& p : img.pixels) ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
  for (const std::string& p : {a, b, c}) std::remove(p.c_str());
}

// lavapipe, which the suite pins, is listed as device 0, a CPU with a compute queue;
// "no Vulkan devices" (exit 0 too) is a failure here.
TEST(Cli, ListDevicesShowsLavapipe) {
  ProcessResult r = RunVkpt({"--list-devices"}, 60.0);
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_TRUE(
      std::regex_search(r.out, std::regex("^0: llvmpipe .*\\(CPU, Vulkan 1\\.[0-9]+\\)$", std::regex::multiline)))
      << r.out;
  EXPECT_EQ(r.out.find("no Vulkan devices"), std::string::npos) << r.out;
}

TEST(Cli, UnknownDeviceIsAnError) {
  const std::string out = TempPath("cli-bad-device.png");
  ProcessResult r = RunVkpt({"--scene", kCornell, "--device", "no-such-gpu-xyz", "--width", "8", "--spp", "1",
                             "--out", out},
                            60.0);
  EXPECT_TRUE(r.ExitedWith(1)) << r.Describe();
  EXPECT_NE(r.err.find("vkpt: error: "), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

// No Vulkan driver at all: pointing the loader at a manifest that does not exist.
const std::vector<std::string> kNoDriver = {"VK_ICD_FILENAMES=/nonexistent/icd.json", "VK_DRIVER_FILES=/nonexistent/icd.json"};

TEST(Cli, ExplicitVulkanWithoutDeviceNamesTheFix) {
  const std::string out = TempPath("cli-no-device.png");
  ProcessResult r = RunVkpt({"--scene", kCornell, "--backend", "vulkan", "--width", "8", "--spp", "1", "--out", out},
                            60.0, "", kNoDriver);
  EXPECT_TRUE(r.ExitedWith(1)) << r.Describe();
  EXPECT_NE(r.err.find("no Vulkan device"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("mesa-vulkan-drivers"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, AutoBackendFallsBackToCpuWithoutDevice) {
  const std::string out = TempPath("cli-fallback.pfm");
  ProcessResult r = RunVkpt({"--scene", kCornell, "--width", "8", "--height", "8", "--spp", "1", "--out", out}, 60.0,
                            "", kNoDriver);
  EXPECT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_NE(r.err.find("rendering on the CPU"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("cpu ("), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(out));
  std::remove(out.c_str());
}

TEST(Cli, ImageBeyondStorageBufferLimitIsRefused) {
  // 4096² pixels need a 512 MiB accumulation buffer: over lavapipe's 128 MiB
  // maxStorageBufferRange. Refused with the limit named, before any rendering.
  const std::string out = TempPath("cli-too-big.png");
  ProcessResult r = RunVkpt({"--scene", kCornell, "--backend", "vulkan", "--width", "4096", "--height", "4096",
                             "--spp", "1", "--out", out},
                            120.0);
  EXPECT_TRUE(r.ExitedWith(1)) << r.Describe();
  EXPECT_NE(r.err.find("maxStorageBufferRange"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, ValidationRunIsClean) {
  const std::string out = TempPath("cli-validation.png");
  ProcessResult r = RunVkpt({"--scene", kCornell, "--backend", "vulkan", "--validation", "--width", "32", "--height",
                             "32", "--spp", "2", "--out", out},
                            120.0);
  EXPECT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
  std::remove(out.c_str());
}

TEST(Cli, CompareReportsAgreementAndWritesHeatmap) {
  const std::string out = TempPath("cli-compare.pfm");
  const std::string heat = TempPath("cli-compare-diff.png");
  ProcessResult r = RunVkpt({"--scene", kCornell, "--compare", "--width", "48", "--height", "48", "--spp", "4",
                             "--out", out},
                            120.0);
  EXPECT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_NE(r.out.find("Lockstep:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("-> agree"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(out));
  EXPECT_TRUE(fs::exists(heat));
  std::remove(out.c_str());
  std::remove(heat.c_str());
}

// --splits spatial on a CAD model (long thin triangles): more references than triangles,
// and the CPU and Vulkan renders still agree.
TEST(Cli, SpatialSplitsRenderAndAgree) {
  VKPT_REQUIRE_SHARED_DATA();
  const std::string out = TempPath("cli-spatial.pfm");
  ProcessResult r = RunVkpt({"--scene", test::CorpusPath("valid/2CylinderEngine/glTF-Binary/2CylinderEngine.glb"),
                             "--splits", "spatial", "--compare", "--width", "40", "--height", "40", "--spp", "4", "--out", out},
                            300.0);
  EXPECT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_NE(r.out.find("-> agree"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("BVH: spatial splits, "), std::string::npos) << r.out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex("scene: (\\d+) triangles \\((\\d+) degenerate.*?(\\d+) triangle references")))
      << r.out;
  EXPECT_GT(std::stoul(m[3]), std::stoul(m[1]) - std::stoul(m[2])) << r.out;
  std::remove(out.c_str());
  std::remove((out.substr(0, out.size() - 4) + "-diff.png").c_str());
}

// By default both trees are built and the one with the lower SAH cost renders; the
// summary names it and the other's cost. The Cornell box's walls enclose the scene:
// spatial splits do not lower its SAH there, so the object tree is kept (a tie).
TEST(Cli, DefaultSplitsAreChosenBySahCost) {
  const std::string out = TempPath("cli-auto-splits.pfm");
  ProcessResult r = RenderCornell(out, {});
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m,
                                std::regex("BVH: object splits \\(auto: spatial splits' SAH cost was ([0-9.]+)\\),.*"
                                           "SAH cost ([0-9.]+),")))
      << r.out;
  EXPECT_GE(std::stod(m[1]), std::stod(m[2])) << r.out;
  ProcessResult object = RenderCornell(out, {"--splits", "object"});
  ASSERT_TRUE(object.ExitedWith(0)) << object.Describe();
  EXPECT_NE(object.out.find("BVH: object splits, "), std::string::npos) << object.out;
  std::remove(out.c_str());
}

TEST(Cli, DiffTellsSameFromDifferentImages) {
  const std::string a = TempPath("cli-diff-a.pfm"), b = TempPath("cli-diff-b.pfm"), c = TempPath("cli-diff-c.pfm");
  ASSERT_TRUE(RenderCornell(a, {"--seed", "1"}).ExitedWith(0));
  ASSERT_TRUE(RenderCornell(b, {"--seed", "1"}).ExitedWith(0));
  ASSERT_TRUE(RenderCornell(c, {"--seed", "1", "--max-depth", "1"}).ExitedWith(0));  // much darker
  ProcessResult same = RunVkpt({"--diff", a, b}, 60.0);
  EXPECT_TRUE(same.ExitedWith(0)) << same.Describe();
  ProcessResult differ = RunVkpt({"--diff", a, c, "--out", TempPath("cli-diff.png")}, 60.0);
  EXPECT_TRUE(differ.ExitedWith(4)) << differ.Describe();
  EXPECT_TRUE(fs::exists(TempPath("cli-diff.png")));
  ProcessResult missing = RunVkpt({"--diff", a, TempPath("no-such.pfm")}, 60.0);
  EXPECT_TRUE(missing.ExitedWith(1)) << missing.Describe();
  for (const std::string& p : {a, b, c, TempPath("cli-diff.png")}) std::remove(p.c_str());
}

// ---------------------------------------------------------------------------------------
// Verbose report

TEST(Cli, VerboseReportsTrianglesAndIgnoredFeatures) {
  VKPT_REQUIRE_SHARED_DATA();
  const std::string scene = test::CorpusPath("valid/BoxTextured/glTF/BoxTextured.gltf");
  const std::string out = TempPath("cli-verbose.png");
  ProcessResult r =
      RunVkpt({"--scene", scene, "-v", "--width", "16", "--height", "16", "--spp", "1", "--out", out}, 60.0);
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_TRUE(std::regex_search(r.out, std::regex("triangles: 12\\b"))) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex("textures: 1 from 1 images, 65536 texels"))) << r.out;
  EXPECT_NE(r.out.find("Mrays/s"), std::string::npos) << r.out;
  std::remove(out.c_str());
}

// `vkpt -v` on the model `b` builds, 16 × 16 at 1 spp, writing image `name` and removing it.
ProcessResult RunVerboseOn(const test::GltfBuilder& b, const std::string& name) {
  const test::TempFile file(b.Json());
  const std::string out = TempPath(name);
  ProcessResult r =
      RunVkpt({"--scene", file.path, "-v", "--width", "16", "--height", "16", "--spp", "1", "--out", out}, 60.0);
  std::remove(out.c_str());
  return r;
}

// The same report for a textured triangle built in code (a 2 × 2 PNG in a bufferView).
TEST(Cli, VerboseReportsTheTexturesOfAGeneratedModel) {
  test::GltfBuilder b;
  const int positions = b.Positions(test::kUnitTriangle);
  const int uv = b.Accessor(b.View(test::Bytes(std::vector<float>{0, 0, 1, 0, 0, 1})), test::kFloat, 3, "VEC2");
  b.meshes.push_back(R"({"primitives":[{"attributes":{"POSITION":)" + std::to_string(positions) + R"(,"TEXCOORD_0":)" +
                     std::to_string(uv) + R"(},"material":0}]})");
  b.materials.push_back(R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}})");
  const std::vector<unsigned char> png = test::MakePng(2, 2, 8, 2, std::vector<uint8_t>(12, 200));
  b.images.push_back(R"({"bufferView":)" + std::to_string(b.View(std::string(png.begin(), png.end()))) +
                     R"(,"mimeType":"image/png"})");
  b.textures.push_back(R"({"source":0})");
  b.Node(R"({"mesh":0})");
  ProcessResult r = RunVerboseOn(b, "cli-verbose-generated.png");
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_TRUE(std::regex_search(r.out, std::regex("triangles: 1\\b"))) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex("textures: 1 from 1 images, 4 texels"))) << r.out;
  EXPECT_EQ(r.out.find("ignored: "), std::string::npos) << r.out;
}

// The layers a material adds (coat, sheen, diffuse transmission, …) are listed with it,
// and a dispersion that nothing shows is said to be unseen.
TEST(Cli, VerboseListsAMaterialsLayers) {
  test::GltfBuilder b;
  b.meshes.push_back(R"({"primitives":[{"attributes":{"POSITION":)" + std::to_string(b.Positions(test::kUnitTriangle)) +
                     R"(},"material":0}]})");
  b.materials.push_back(
      R"({"extensions":{"KHR_materials_clearcoat":{"clearcoatFactor":0.5,"clearcoatRoughnessFactor":0.25},)"
      R"("KHR_materials_sheen":{"sheenColorFactor":[1,0.5,0.25],"sheenRoughnessFactor":0.75},)"
      R"("KHR_materials_diffuse_transmission":{"diffuseTransmissionFactor":0.3},)"
      R"("KHR_materials_iridescence":{"iridescenceFactor":1,"iridescenceThicknessMaximum":500},)"
      R"("KHR_materials_anisotropy":{"anisotropyStrength":0.5,"anisotropyRotation":1},)"
      R"("KHR_materials_dispersion":{"dispersion":0.5}}})");
  b.extensionsUsed = {"KHR_materials_clearcoat",   "KHR_materials_sheen",      "KHR_materials_diffuse_transmission",
                      "KHR_materials_iridescence", "KHR_materials_anisotropy", "KHR_materials_dispersion"};
  b.Node(R"({"mesh":0})");
  ProcessResult r = RunVerboseOn(b, "cli-verbose-layers.png");
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_NE(r.out.find("clearcoat 0.5 (roughness 0.25) sheen (1, 0.5, 0.25) roughness 0.75 diffuse transmission 0.3 "
                       "(1, 1, 1) anisotropy 0.5 (rotation 1 rad) dispersion 0.5 (Abbe number 40; unseen: it needs a "
                       "transmissive volume of ior > 1) iridescence 1 (ior 1.3, 500-500 nm)"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("ignored: "), std::string::npos) << r.out;
}

void ExpectQuiet(const std::string& scene) {
  const std::string out = TempPath("cli-quiet.png");
  ProcessResult r = RunVkpt({"--scene", scene, "--width", "16", "--height", "16", "--spp", "1", "--out", out}, 60.0);
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_EQ(r.out.find("ignored:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Mrays/s"), std::string::npos) << r.out;
  // Nothing from vkpt itself on stderr (a Vulkan driver may print its own notices).
  EXPECT_FALSE(std::regex_search(r.err, std::regex("(^|\\n)vkpt:"))) << r.err;
  std::remove(out.c_str());
}

TEST(Cli, QuietByDefault) { ExpectQuiet(test::SourcePath("scenes/cornell.gltf")); }

TEST(Cli, QuietByDefaultWithTextures) {
  VKPT_REQUIRE_SHARED_DATA();
  ExpectQuiet(test::CorpusPath("valid/BoxTextured/glTF/BoxTextured.gltf"));
}

}  // namespace
}  // namespace vkpt::internal

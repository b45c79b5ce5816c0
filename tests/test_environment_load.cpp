// Reading environment maps (.hdr, .exr) as untrusted input, and --env on the command line:
// every bad file is one clear error naming it, found before decoding where its header
// suffices; the GPU binds the map without a validation message.
#include <sys/stat.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>

#include <tinyexr.h>

#include "image/image_load.h"
#include "scene/load_limits.h"
#include "test_util.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

const std::string kVenice = test::SharedData("gltf-pbr/environments/venice_sunset_1k.hdr");

void WriteFile(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// The message ReadEnvironmentImage fails with ("" if it succeeds); `charged` collects
// what it asked for.
std::string LoadError(const std::string& path, std::vector<std::string>* charged = nullptr) {
  std::vector<std::string> warnings;
  try {
    ReadEnvironmentImage(
        path,
        [&](uint64_t, const std::string& what) {
          if (charged) charged->push_back(what);
        },
        &warnings);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// A Radiance file of w × h flat (not run-length encoded) RGBE texels of value 1.
std::string FlatHdr(int w, int h) {
  std::string s = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(h) + " +X " + std::to_string(w) + "\n";
  for (int i = 0; i < w * h; ++i) s += std::string("\x80\x80\x80\x81", 4);
  return s;
}

TEST(EnvironmentLoad, ReadsTheRadianceMap) {
  VKPT_REQUIRE_SHARED_DATA();
  std::vector<std::string> charged;
  std::vector<std::string> warnings;
  Image image = ReadEnvironmentImage(
      kVenice, [&](uint64_t, const std::string& what) { charged.push_back(what); }, &warnings);
  EXPECT_EQ(image.width, 1024u);
  EXPECT_EQ(image.height, 512u);
  EXPECT_EQ(charged, (std::vector<std::string>{"the file", "its decoded texels"}));
  float brightest = 0.0f;
  for (const glm::vec3& p : image.pixels) brightest = std::max(brightest, p.x);
  EXPECT_GT(brightest, 1000.0f);  // the sun (MANIFEST: max luminance 2106)
}

TEST(EnvironmentLoad, SmallFlatFileDecodesExactly) {
  const std::string dir = test::FreshTempDirectory("env-flat");
  WriteFile(dir + "/flat.hdr", FlatHdr(4, 2));
  std::vector<std::string> warnings;
  Image image = ReadEnvironmentImage(
      dir + "/flat.hdr", [](uint64_t, const std::string&) {}, &warnings);
  ASSERT_EQ(image.pixels.size(), 8u);
  for (const glm::vec3& p : image.pixels) EXPECT_EQ(p, glm::vec3(1.0f));
}

TEST(EnvironmentLoad, BadFilesAreNamedErrors) {
  const std::string dir = test::FreshTempDirectory("env-bad");
  const std::string rle = test::RleHdr(256, 128);
  WriteFile(dir + "/cut.hdr", rle.substr(0, rle.size() * 6 / 10));
  WriteFile(dir + "/cutflat.hdr", FlatHdr(4, 2).substr(0, FlatHdr(4, 2).size() - 5));
  WriteFile(dir + "/garbage.hdr", std::string(5000, '\x5a'));
  WriteFile(dir + "/header.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 10 +X 20000\n" + std::string(64, '\0'));
  WriteFile(dir + "/empty.exr", "");
  WriteFile(dir + "/garbage.exr", std::string("\x76\x2f\x31\x01\x02\0\0\0", 8) + std::string(300, '\x7f'));
  // Run-length counts of 0 make no progress: this stb version would loop forever on them.
  WriteFile(dir + "/zeroruns.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 16\n" +
                                       std::string("\x02\x02\x00\x10", 4) + std::string(100, '\0'));
  WriteFile(dir + "/map.png", "not an environment");
  std::filesystem::create_directory(dir + "/folder.hdr");
  ASSERT_EQ(mkfifo((dir + "/fifo.hdr").c_str(), 0600), 0);
  const std::vector<std::pair<std::string, std::string>> cases = {{"cut.hdr", "is truncated"},
                                                                  {"cutflat.hdr", "is truncated"},
                                                                  {"garbage.hdr", "not a Radiance HDR file"},
                                                                  {"header.hdr", "is 20000 × 10 pixels"},
                                                                  {"empty.exr", "not an OpenEXR file"},
                                                                  {"garbage.exr", "cannot read the OpenEXR header"},
                                                                  {"zeroruns.hdr", "is truncated"},
                                                                  {"map.png", "unknown environment map format"},
                                                                  {"folder.hdr", "is a directory"},
                                                                  {"fifo.hdr", "is a FIFO"},
                                                                  {"missing.hdr", "does not exist"}};
  for (const auto& [name, problem] : cases) {
    std::vector<std::string> charged;
    std::string message = LoadError(dir + "/" + name, &charged);
    std::printf("%s\n", message.c_str());
    EXPECT_EQ(message.rfind(dir + "/" + name + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << message;
    // Oversized dimensions are refused from the header: nothing charged for texels.
    if (name == "header.hdr") {
      EXPECT_EQ(charged, std::vector<std::string>{"the file"});
    }
  }
}

TEST(EnvironmentLoad, ExrNegativesAreClampedAndNonFiniteRefused) {
  const std::string dir = test::FreshTempDirectory("env-exr");
  Image image(3, 2);
  image.At(0, 0) = glm::vec3(1.0f, 2.0f, 3.0f);
  image.At(1, 1) = glm::vec3(-0.5f, 4.0f, 0.0f);
  WriteImage(image, dir + "/map.exr");
  std::vector<std::string> warnings;
  Image read = ReadEnvironmentImage(
      dir + "/map.exr", [](uint64_t, const std::string&) {}, &warnings);
  EXPECT_EQ(read.At(0, 0), glm::vec3(1.0f, 2.0f, 3.0f));
  EXPECT_EQ(read.At(1, 1), glm::vec3(0.0f, 4.0f, 0.0f));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("1 texel(s) had negative components"), std::string::npos) << warnings[0];
  image.At(2, 1).y = std::numeric_limits<float>::infinity();
  WriteImage(image, dir + "/map.exr");
  EXPECT_NE(LoadError(dir + "/map.exr").find("texel (2, 1) is not finite"), std::string::npos);
}

// An EXR whose R, G and B hold 32-bit integers (an ID map, not radiance): refused by name.
TEST(EnvironmentLoad, ExrIntegerChannelsAreRefused) {
  const std::string dir = test::FreshTempDirectory("env-exr-uint");
  std::vector<uint32_t> plane(4 * 2, 7u);
  unsigned char* planes[3] = {reinterpret_cast<unsigned char*>(plane.data()),
                              reinterpret_cast<unsigned char*>(plane.data()),
                              reinterpret_cast<unsigned char*>(plane.data())};
  EXRChannelInfo channels[3] = {};
  for (int c = 0; c < 3; ++c) channels[c].name[0] = "BGR"[c];
  int types[3] = {TINYEXR_PIXELTYPE_UINT, TINYEXR_PIXELTYPE_UINT, TINYEXR_PIXELTYPE_UINT};
  EXRHeader header;
  InitEXRHeader(&header);
  header.num_channels = 3;
  header.channels = channels;
  header.pixel_types = types;
  header.requested_pixel_types = types;
  EXRImage image;
  InitEXRImage(&image);
  image.num_channels = 3;
  image.width = 4;
  image.height = 2;
  image.images = planes;
  const char* err = nullptr;
  ASSERT_EQ(SaveEXRImageToFile(&image, &header, (dir + "/ids.exr").c_str(), &err), TINYEXR_SUCCESS) << err;
  EXPECT_NE(LoadError(dir + "/ids.exr").find("ids.exr: channel B holds integers; an environment map needs floats"),
            std::string::npos)
      << LoadError(dir + "/ids.exr");
  std::filesystem::remove_all(dir);
}

TEST(EnvironmentLoad, MemoryIsChargedBeforeItIsSpent) {
  // 1024 × 512 texels: a 0.7 MB file decoding to 12 MB.
  const std::string map = test::TempPath("env-budget.hdr");
  WriteFile(map, test::RleHdr(1024, 512));
  for (uint64_t limit : {uint64_t(256) << 10, uint64_t(4) << 20}) {
    MemoryBudget budget(limit, map);
    std::vector<std::string> warnings;
    try {
      ReadEnvironmentImage(
          map, [&](uint64_t bytes, const std::string& what) { budget.Charge(bytes, what); }, &warnings);
      ADD_FAILURE() << "a 0.7 MB file decoding to 12 MB fit in " << limit;
    } catch (const Error& e) {
      std::printf("%s\n", e.what());
      EXPECT_NE(std::string(e.what()).find(limit < (2 << 20) ? "the file needs" : "its decoded texels needs"),
                std::string::npos);
    }
  }
  std::remove(map.c_str());
}

TEST(EnvironmentCli, UsageErrorsAndMissingFiles) {
  const std::string scene = test::SourcePath("scenes/cornell.gltf"), out = test::TempPath("env-cli.png");
  const std::string map = test::TempPath("env-cli.hdr");
  WriteFile(map, test::RleHdr(64, 32));
  test::ProcessResult both = test::RunVkpt({"--scene", scene, "--env", map, "--background", "1", "--out", out});
  EXPECT_TRUE(both.ExitedWith(2)) << both.Describe();
  EXPECT_NE(both.err.find("--env and --background"), std::string::npos) << both.err;
  test::ProcessResult orphan = test::RunVkpt({"--scene", scene, "--env-rotation", "90", "--out", out});
  EXPECT_TRUE(orphan.ExitedWith(2)) << orphan.Describe();
  test::ProcessResult missing = test::RunVkpt({"--scene", scene, "--env", "/nonexistent/sky.hdr", "--out", out});
  EXPECT_TRUE(missing.ExitedWith(1)) << missing.Describe();
  EXPECT_EQ(missing.err, "vkpt: error: /nonexistent/sky.hdr: does not exist\n");
  EXPECT_FALSE(std::filesystem::exists(out));
  std::remove(map.c_str());
}

// The map uploaded and bound next to the scene: a render under the validation layer
// (exit 3 on any message), and -v reporting the map.
TEST(EnvironmentCli, GpuBindsTheMapWithoutValidationMessages) {
  const std::string out = test::TempPath("env-gpu.png"), map = test::TempPath("env-gpu.hdr");
  WriteFile(map, test::RleHdr(1024, 512));
  test::ProcessResult r = test::RunVkpt({"--scene", test::SourcePath("scenes/cornell.gltf"), "--env", map,
                                         "--env-rotation", "90", "--env-intensity", "0.5", "--backend", "vulkan",
                                         "--validation", "--spp", "2", "--width", "32", "--out", out, "-v"});
  EXPECT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_NE(r.out.find("1024 × 512 texels, intensity 0.5; distribution built in"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("environment: rotated 90° about +Y"), std::string::npos) << r.out;
  std::remove(map.c_str());
  std::remove(out.c_str());
}

}  // namespace
}  // namespace vkpt::internal

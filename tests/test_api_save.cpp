// vkpt::Save writes a library render as the command line writes the same render: the
// same bytes in EXR (with AOV layers), PNG (through the default view, AOV pictures
// beside it) and PFM, and the raw image beside a denoised one.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "api_test_util.h"
#include "test_util.h"

#include "vkpt/vkpt.h"

namespace vkpt::internal {
namespace {

const std::string kCornell = test::Cornell();

// The command line's render of the Cornell box on the CPU with `extra`, into `out`.
void CliRender(std::vector<std::string> extra, const std::string& out) {
  std::vector<std::string> args = {"--scene", kCornell, "--backend", "cpu", "--width", "24", "--height", "16",
                                   "--spp",   "4",      "--chunk",   "4",   "--seed",  "5",  "--out",    out};
  args.insert(args.end(), extra.begin(), extra.end());
  const test::ProcessResult r = test::RunVkpt(args);
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
}

vkpt::Scene CpuScene() {
  vkpt::SceneOptions cpu;
  cpu.backend = vkpt::Backend::Cpu;
  return vkpt::Scene(kCornell, cpu);
}

TEST(ApiSave, FilesEqualTheCommandLines) {
  const std::string dir = test::FreshTempDirectory("api-save");
  vkpt::Scene scene = CpuScene();
  vkpt::RenderOptions options = test::SmallRender(5);
  options.aovs = {"normal", "depth", "albedo"};
  const vkpt::RenderResult result = scene.Render(vkpt::Camera{}, options);
  for (const std::string ext : {"exr", "png", "pfm"}) {
    CliRender({"--aov", "normal,depth,albedo"}, dir + "/cli." + ext);
    const std::vector<std::string> files = Save(result, dir + "/api." + ext);
    const std::vector<std::string> tags =
        ext == "exr" ? std::vector<std::string>{""} : std::vector<std::string>{"", ".albedo", ".normal", ".depth"};
    EXPECT_EQ(files.size(), tags.size()) << ext;
    for (const std::string& tag : tags)
      EXPECT_EQ(test::ReadFile(dir + "/api" + tag + "." + ext), test::ReadFile(dir + "/cli" + tag + "." + ext))
          << tag << "." << ext;
  }
  // Another view and exposure change the picture, as --view and --exposure do.
  CliRender({"--view", "agx", "--exposure", "1.5"}, dir + "/agx.png");
  Save(scene.Render(vkpt::Camera{}, test::SmallRender(5)), dir + "/api-agx.png", "agx", 1.5f);
  EXPECT_EQ(test::ReadFile(dir + "/api-agx.png"), test::ReadFile(dir + "/agx.png"));
  EXPECT_NE(test::ReadFile(dir + "/api-agx.png"), test::ReadFile(dir + "/api.png"));
}

TEST(ApiSave, DenoisedRenderKeepsItsRawImageBeside) {
  const std::string dir = test::FreshTempDirectory("api-save-denoise");
  vkpt::Scene scene = CpuScene();
  vkpt::RenderOptions options = test::SmallRender(5);
  options.denoise = true;
  const std::vector<std::string> files = Save(scene.Render(vkpt::Camera{}, options), dir + "/api.pfm");
  ASSERT_EQ(files, (std::vector<std::string>{dir + "/api.pfm", dir + "/api.raw.pfm"}));
  CliRender({"--denoise"}, dir + "/cli.pfm");
  EXPECT_EQ(test::ReadFile(dir + "/api.pfm"), test::ReadFile(dir + "/cli.pfm"));
  EXPECT_EQ(test::ReadFile(dir + "/api.raw.pfm"), test::ReadFile(dir + "/cli.raw.pfm"));
}

TEST(ApiSave, RefusesWhatItCannotWrite) {
  const std::string dir = test::FreshTempDirectory("api-save-errors");
  vkpt::Scene scene = CpuScene();
  vkpt::RenderResult result = scene.Render(vkpt::Camera{}, test::SmallRender(5));
  auto message = [&](const std::string& path, const std::string& view = "neutral") {
    try {
      Save(result, path, view);
    } catch (const vkpt::Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(dir + "/a.png", "filmic"), "unknown view \"filmic\" (neutral, agx, aces or clamp)");
  EXPECT_NE(message(dir + "/a.jpg").find("a.jpg"), std::string::npos) << message(dir + "/a.jpg");
  result.aovs["depth"] = {2, 2, 1, {"Z"}, std::vector<float>(4, 1.0f)};
  EXPECT_EQ(message(dir + "/a.exr"), "AOV \"depth\" does not match the image's size");
  result.aovs.clear();
  result.image.data.pop_back();
  EXPECT_EQ(message(dir + "/a.exr"), "an image to save needs 3 channels of width × height values");
  EXPECT_FALSE(std::filesystem::exists(dir + "/a.exr"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/a.png"));
}

}  // namespace
}  // namespace vkpt::internal

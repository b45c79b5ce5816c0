// SceneOptions::log: the load's and a render's warnings reach the caller, in the API's
// terms, with their levels; the -v details come as Debug.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "api_test_util.h"
#include "test_util.h"

#include "vkpt/vkpt.h"

namespace vkpt::internal {
namespace {

struct Logged {
  vkpt::LogLevel level;
  std::string message;
};

// The Cornell box declaring an extension vkpt does not know, with its light put out.
std::string DarkCornellWithAnUnknownExtension(const test::TempFolder& folder) {
  std::ifstream in(test::Cornell());
  nlohmann::json file = nlohmann::json::parse(in);
  file["extensionsUsed"].push_back("EXT_made_up");
  file["materials"][3]["emissiveFactor"] = {0, 0, 0};
  std::filesystem::copy_file(test::SourcePath("scenes/cornell.bin"), folder / "cornell.bin");
  std::ofstream(folder / "cornell.gltf") << file.dump();
  return folder / "cornell.gltf";
}

bool Has(const std::vector<Logged>& log, vkpt::LogLevel level, const std::string& part) {
  for (const Logged& l : log)
    if (l.level == level && l.message.find(part) != std::string::npos) return true;
  return false;
}

TEST(ApiLog, WarningsReachTheCallerInTheApisTerms) {
  const test::TempFolder folder("api-log");
  const std::string path = DarkCornellWithAnUnknownExtension(folder);
  for (vkpt::Backend backend : {vkpt::Backend::Cpu, vkpt::Backend::Vulkan}) {
    std::vector<Logged> log;
    vkpt::SceneOptions options;
    options.backend = backend;
    options.log = [&log](vkpt::LogLevel level, const std::string& message) { log.push_back({level, message}); };
    vkpt::Scene scene(path, options);
    EXPECT_TRUE(Has(log, vkpt::LogLevel::Warning, path + ": ignored: extension EXT_made_up"));
    vkpt::RenderOptions black = test::SmallRender();
    black.background = vkpt::Rgb{0.0f, 0.0f, 0.0f};
    scene.Render({}, black);
    EXPECT_TRUE(Has(log, vkpt::LogLevel::Warning, "no lights and a black background"));
    EXPECT_TRUE(Has(log, vkpt::LogLevel::Debug, "pass 1: samples 0..0"));
    for (const Logged& l : log) EXPECT_EQ(l.message.find("--"), std::string::npos) << l.message;
  }
}

TEST(ApiLog, WithoutACallbackNothingIsSaid) {
  const test::TempFolder folder("api-log-none");
  vkpt::SceneOptions options;
  options.backend = vkpt::Backend::Cpu;
  vkpt::Scene scene(DarkCornellWithAnUnknownExtension(folder), options);
  EXPECT_EQ(scene.Render({}, test::SmallRender()).spp, 4u);
}

}  // namespace
}  // namespace vkpt::internal

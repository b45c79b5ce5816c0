// Messages leave the library in its own terms (vkpt/api_terms.h): every command-line option
// that a message of the layers under the API names has a translation.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "test_util.h"
#include "vkpt/api_terms.h"

namespace vkpt::internal {
namespace {

TEST(ApiTerms, EveryOptionInTheEnginesMessagesIsTranslated) {
  // A string literal that names an option: "…--max-memory…".
  const std::regex literal(R"("(?:[^"\\]|\\.)*--[a-z](?:[^"\\]|\\.)*")"), option("--[a-z]");
  const std::regex command("`vkpt --[a-z-]+`");  // the command line named as such
  int literals = 0;
  for (const char* layer : {"gltf", "scene", "vk", "engine", "render", "session", "cpu", "image", "bvh", "util"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(test::SourcePath("host/") + layer)) {
      std::ifstream in(entry.path());
      std::string line;
      for (int n = 1; std::getline(in, line); ++n) {
        if (line.find_first_not_of(' ') != std::string::npos && line.compare(line.find_first_not_of(' '), 2, "//") == 0)
          continue;  // a comment
        for (std::sregex_iterator it(line.begin(), line.end(), literal), end; it != end; ++it, ++literals) {
          const std::string translated = InApiTerms(it->str());
          EXPECT_FALSE(std::regex_search(std::regex_replace(translated, command, ""), option))
              << entry.path().string() << ":" << n << ": " << it->str() << " becomes " << translated;
        }
      }
    }
  }
  std::printf("%d message literals name command-line options\n", literals);
  EXPECT_GE(literals, 20);
}

TEST(ApiTerms, OptionsBecomeSettings) {
  EXPECT_EQ(InApiTerms("a.glb: 3 GiB, more than --max-memory 1 GiB allows (raise --max-memory if genuine)"),
            "a.glb: 3 GiB, more than SceneOptions::maxMemory 1 GiB allows (raise SceneOptions::maxMemory if genuine)");
  EXPECT_EQ(InApiTerms("use a smaller --width/--height or --backend cpu"),
            "use a smaller RenderOptions::width/height or Backend::Cpu");
  EXPECT_EQ(InApiTerms("--device 2: there are only 1 Vulkan device(s) (see --list-devices)"),
            "SceneOptions::device 2: there are only 1 Vulkan device(s) (`vkpt --list-devices` lists them)");
  EXPECT_EQ(InApiTerms("no option here -- or here"), "no option here -- or here");
}

TEST(ApiTerms, PythonReadsItsKeywords) {
  const std::string cpp = InApiTerms("use a smaller --width/--height or --backend cpu; --allow-external-uris; --orbit");
  EXPECT_EQ(cpp,
            "use a smaller RenderOptions::width/height or Backend::Cpu; SceneOptions::allowExternalUris; "
            "Camera::orbitDegrees");
  EXPECT_EQ(InTerms(cpp, Terms::kCpp, Terms::kPython),
            "use a smaller width/height or backend=\"cpu\"; allow_external_uris; Camera.orbit");
  EXPECT_EQ(InTerms("SceneOptions::maxMemory", Terms::kCpp, Terms::kCommandLine), "--max-memory");
}

}  // namespace
}  // namespace vkpt::internal

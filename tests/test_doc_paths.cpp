// The README and docs/architecture.md name the files and folders of the tree; every one
// they name must exist, so that neither describes a place that has moved.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "test_util.h"

namespace vkpt::internal {
namespace {

// The paths a document names in backticks: a folder ("host/vk/") or a file with an
// extension ("vkpt/client.cpp"), "../shared/…" models aside. Other slashes ("JOINTS_0/1")
// are no paths.
std::vector<std::string> NamedPaths(const std::string& text) {
  const std::regex named(R"(`([A-Za-z0-9_.-]+/[A-Za-z0-9_./-]*)`)");
  const std::regex path(R"(.*/$|.*\.(h|cpp|md|glsl|comp|py|sh|cmake|txt|json|gltf|glb|hdr|exr|pyi)$)");
  std::vector<std::string> paths;
  for (std::sregex_iterator it(text.begin(), text.end(), named), end; it != end; ++it)
    if (std::regex_match((*it)[1].str(), path)) paths.push_back((*it)[1].str());
  return paths;
}

// Where a named path may be: from the top of the tree, or under an include root (the
// docs write "vkpt/client.cpp" as the code includes it), or beside the tree in ../shared.
bool Exists(const std::string& named) {
  for (const char* root : {"", "host/", "shaders/", "include/", "docs/", "../shared/"})
    if (std::filesystem::exists(test::SourcePath(std::string(root) + named))) return true;
  return false;
}

std::vector<std::string> Missing(const std::string& text) {
  std::vector<std::string> missing;
  for (const std::string& p : NamedPaths(text))
    if (!Exists(p) && p.rfind("gltf-", 0) != 0) missing.push_back(p);  // ../shared's folders, when absent
  return missing;
}

TEST(DocPaths, EveryFileTheReadmeAndTheArchitectureNameExists) {
  for (const char* doc : {"README.md", "docs/architecture.md"}) {
    const std::string text = test::ReadFile(test::SourcePath(doc));
    EXPECT_GE(NamedPaths(text).size(), 20u) << doc;
    EXPECT_EQ(Missing(text), std::vector<std::string>{}) << doc;
  }
}

TEST(DocPaths, TheReadmeIsALandingPage) {
  const std::string readme = test::ReadFile(test::SourcePath("README.md"));
  EXPECT_LE(std::count(readme.begin(), readme.end(), '\n'), 200) << "README.md: move detail to docs/";
}

TEST(DocPaths, AMovedFileIsCaught) {
  EXPECT_EQ(Missing("the film (`render/film.h`), the API (`vkpt/vkpt.h`), `host/vk/`"), std::vector<std::string>{});
  EXPECT_EQ(Missing("the film (`image/film.h`) and `host/images/`, not `JOINTS_0/1`"),
            (std::vector<std::string>{"image/film.h", "host/images/"}));
}

}  // namespace
}  // namespace vkpt::internal

// The shared glTF corpus (gltf-corpus/ of the test data, test_util.h; read in place): every valid model loads
// with the triangle count MANIFEST.md gives and renders; every invalid file makes the
// binary exit 1 with a clear message and no output image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "gltf/gltf_loader.h"
#include "image/image.h"
#include "test_util.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

namespace fs = std::filesystem;
using test::CorpusPath;
using test::RunVkpt;
using test::TempPath;

constexpr size_t kValidModels = 25;
constexpr size_t kInvalidCases = 54;

bool IsGltf(const fs::path& p) { return p.extension() == ".gltf" || p.extension() == ".glb"; }

bool CorpusPresent() { return fs::is_directory(CorpusPath("valid")) && fs::is_directory(CorpusPath("invalid")); }

std::string Trim(const std::string& s) {
  size_t b = s.find_first_not_of(" \t\r");
  size_t e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

std::vector<std::string> SplitRow(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  std::string cell;
  std::getline(ss, cell, '|');  // text before the first '|'
  while (std::getline(ss, cell, '|')) cells.push_back(Trim(cell));
  if (!cells.empty() && cells.back().empty()) cells.pop_back();  // after the last '|'
  return cells;
}

// A Markdown table of MANIFEST.md: the rows after the header that starts with
// `firstColumn`, as column name → cell.
std::vector<std::map<std::string, std::string>> ManifestTable(const std::string& firstColumn) {
  std::ifstream in(CorpusPath("MANIFEST.md"));
  std::vector<std::map<std::string, std::string>> rows;
  std::vector<std::string> header;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("|", 0) != 0) {
      if (!header.empty()) break;  // end of the table
      continue;
    }
    std::vector<std::string> cells = SplitRow(line);
    if (header.empty()) {
      if (!cells.empty() && cells[0] == firstColumn) header = cells;
      continue;
    }
    if (!cells.empty() && cells[0].find_first_not_of("-: ") == std::string::npos) continue;  // |---|
    std::map<std::string, std::string> row;
    for (size_t i = 0; i < header.size() && i < cells.size(); ++i) row[header[i]] = cells[i];
    rows.push_back(row);
  }
  return rows;
}

struct ValidModel {
  std::string dir;   // "valid/<Model>/<variant>", as MANIFEST.md names it
  std::string file;  // the .gltf/.glb in it
  std::string name;  // test name
};

// How GoogleTest prints the parameter (in ctest's test names too).
void PrintTo(const ValidModel& m, std::ostream* os) { *os << m.dir << "/" << m.file; }

std::string TestName(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

// valid/<Model>/<variant>/<main file>: every .gltf/.glb two levels below valid/.
std::vector<ValidModel> DiscoverValid() {
  std::vector<ValidModel> models;
  std::error_code ec;
  if (!fs::is_directory(CorpusPath("valid"), ec)) return models;
  for (const fs::directory_entry& model : fs::directory_iterator(CorpusPath("valid"), ec)) {
    if (!model.is_directory()) continue;
    for (const fs::directory_entry& variant : fs::directory_iterator(model.path(), ec)) {
      if (!variant.is_directory()) continue;
      for (const fs::directory_entry& f : fs::directory_iterator(variant.path(), ec)) {
        if (!f.is_regular_file() || !IsGltf(f.path())) continue;
        ValidModel m;
        m.dir = "valid/" + model.path().filename().string() + "/" + variant.path().filename().string();
        m.file = f.path().filename().string();
        m.name = TestName(model.path().filename().string() + "_" + variant.path().filename().string() + "_" +
                          f.path().extension().string().substr(1));
        models.push_back(m);
      }
    }
  }
  std::sort(models.begin(), models.end(), [](const ValidModel& a, const ValidModel& b) { return a.name < b.name; });
  return models;
}

std::vector<std::string> DiscoverInvalid() {
  std::vector<std::string> files;
  std::error_code ec;
  if (!fs::is_directory(CorpusPath("invalid"), ec)) return files;
  for (const fs::directory_entry& f : fs::directory_iterator(CorpusPath("invalid"), ec))
    if (f.is_regular_file() && IsGltf(f.path())) files.push_back(f.path().filename().string());
  std::sort(files.begin(), files.end());
  return files;
}

bool AllFinite(const Image& img) {
  for (const glm::vec3& p : img.pixels)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
  return true;
}

// ---------------------------------------------------------------------------------------

TEST(Corpus, CaseCountsMatchManifest) {
  VKPT_REQUIRE_SHARED_DATA();
  ASSERT_TRUE(CorpusPresent()) << CorpusPath("") << " has no valid/ and invalid/";
  std::vector<ValidModel> valid = DiscoverValid();
  std::vector<std::string> invalid = DiscoverInvalid();
  EXPECT_EQ(valid.size(), kValidModels);
  EXPECT_EQ(invalid.size(), kInvalidCases);

  auto validRows = ManifestTable("dir");
  auto invalidRows = ManifestTable("case");
  EXPECT_EQ(validRows.size(), kValidModels) << "valid table rows in MANIFEST.md";
  EXPECT_EQ(invalidRows.size(), kInvalidCases) << "invalid table rows in MANIFEST.md";
  // Directory and manifest agree, both ways.
  std::map<std::string, std::string> mainFile;
  for (auto& r : validRows) mainFile[r["dir"]] = r["main file"];
  for (const ValidModel& m : valid) {
    auto it = mainFile.find(m.dir);
    if (it == mainFile.end()) ADD_FAILURE() << m.dir << " is not in MANIFEST.md";
    else EXPECT_EQ(it->second, m.file) << m.dir;
  }
  std::vector<std::string> listed;
  for (auto& r : invalidRows) listed.push_back(r["case"]);
  std::sort(listed.begin(), listed.end());
  EXPECT_EQ(listed, invalid) << "invalid/ and MANIFEST.md's invalid table differ";
}

// ---------------------------------------------------------------------------------------
// Valid models

class CorpusValid : public ::testing::TestWithParam<ValidModel> {};

TEST_P(CorpusValid, LoadsWithManifestTriangleCountAndRenders) {
  VKPT_REQUIRE_SHARED_DATA();
  const ValidModel& m = GetParam();
  const std::string path = CorpusPath(m.dir + "/" + m.file);

  // The manifest's scene_tris for this directory.
  long long expectedTris = -1;
  for (auto& r : ManifestTable("dir"))
    if (r["dir"] == m.dir) {
      EXPECT_EQ(r["main file"], m.file);
      expectedTris = std::stoll(r["scene_tris"]);
    }
  ASSERT_GE(expectedTris, 0) << m.dir << " has no scene_tris in MANIFEST.md";

  Scene scene;
  try {
    scene = LoadGltf(path);
  } catch (const Error& e) {
    FAIL() << "LoadGltf threw: " << e.what();
  }
  EXPECT_EQ(scene.triangles.size(), size_t(expectedTris)) << path;
  EXPECT_EQ(scene.materials.size(), scene.materialNames.size());
  for (const SceneTriangle& t : scene.triangles) {
    ASSERT_LT(t.material, scene.materials.size());
    ASSERT_TRUE(std::isfinite(t.v0.x + t.v0.y + t.v0.z + t.v1.x + t.v1.y + t.v1.z + t.v2.x + t.v2.y + t.v2.z));
  }

  const std::string out = TempPath("corpus-" + m.name + ".pfm");
  std::remove(out.c_str());
  test::ProcessResult r =
      RunVkpt({"--scene", path, "--spp", "2", "--width", "32", "--height", "32", "--out", out}, 60.0);
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  ASSERT_TRUE(fs::exists(out)) << out;
  Image img = ReadPfm(out);
  std::remove(out.c_str());
  EXPECT_EQ(img.width, 32u);
  EXPECT_EQ(img.height, 32u);
  EXPECT_TRUE(AllFinite(img)) << "NaN/Inf in the rendered image of " << path;
}

// Without the test data there is no model to instantiate: CaseCountsMatchManifest skips.
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(CorpusValid);
INSTANTIATE_TEST_SUITE_P(Corpus, CorpusValid, ::testing::ValuesIn(DiscoverValid()),
                         [](const ::testing::TestParamInfo<ValidModel>& info) { return info.param.name; });

// ---------------------------------------------------------------------------------------
// Invalid files

class CorpusInvalid : public ::testing::TestWithParam<std::string> {};

TEST_P(CorpusInvalid, ExitsWithErrorAndWritesNothing) {
  VKPT_REQUIRE_SHARED_DATA();
  const std::string path = CorpusPath("invalid/" + GetParam());
  const std::string out = TempPath("corpus-invalid-" + TestName(GetParam()) + ".pfm");
  std::remove(out.c_str());
  test::ProcessResult r =
      RunVkpt({"--scene", path, "--spp", "2", "--width", "32", "--height", "32", "--out", out}, 60.0);
  EXPECT_FALSE(r.timedOut) << r.Describe();
  EXPECT_EQ(r.signal, 0) << r.Describe();
  EXPECT_TRUE(r.ExitedWith(1)) << r.Describe();
  EXPECT_EQ(r.err.rfind("vkpt: error: ", 0), 0u) << r.Describe();
  EXPECT_NE(r.err.find(path), std::string::npos) << "the message does not name the file: " << r.err;
  EXPECT_FALSE(fs::exists(out)) << "an output image was written for an invalid scene";
  std::remove(out.c_str());
  std::string message = r.err.substr(0, r.err.find('\n'));
  RecordProperty("message", message);
  std::cout << "  " << GetParam() << ": " << message << "\n";
}

GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(CorpusInvalid);
INSTANTIATE_TEST_SUITE_P(Corpus, CorpusInvalid, ::testing::ValuesIn(DiscoverInvalid()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return TestName(info.param); });

// ---------------------------------------------------------------------------------------
// The glTF PBR models (gltf-pbr/ of the test data): test_gpu.cpp renders them on both backends;
// here the command line reports the textures of a textured one.

TEST(CorpusPbr, VerboseListsTheTextures) {
  VKPT_REQUIRE_SHARED_DATA();
  const std::string path = test::SharedData("gltf-pbr/EmissiveStrengthTest/glTF-Binary/EmissiveStrengthTest.glb");
  ASSERT_TRUE(fs::exists(path)) << path << " is missing";
  const std::string out = TempPath("corpus-pbr-verbose.pfm");
  test::ProcessResult r = RunVkpt(
      {"--scene", path, "--backend", "cpu", "--spp", "1", "--width", "16", "--height", "16", "-v", "--out", out}, 60.0);
  std::remove(out.c_str());
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_NE(r.out.find("textures: 1 from 1 images"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("ignored: "), std::string::npos) << r.out;
}

}  // namespace
}  // namespace vkpt::internal

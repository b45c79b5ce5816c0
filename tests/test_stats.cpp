// --stats FILE.json, run as a subprocess: the keys are exactly the schema table of docs/stats.md,
// the values describe the run (the image's mean, the options, the rates), the scene hash
// follows the content, and a failed run leaves no stats file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "image/image.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::ProcessResult;
using test::RunVkpt;
using test::SourcePath;
using test::TempPath;

const std::string kCornell = SourcePath("scenes/cornell.gltf");

ProcessResult Render(const std::string& scene, const std::string& out, const std::string& stats,
                     std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"--scene", scene, "--width", "24", "--height", "24",
                                   "--spp",   "2",   "--out",   out,  "--stats",  stats};
  args.insert(args.end(), extra.begin(), extra.end());
  return RunVkpt(args, 120.0);
}

json ReadJson(const std::string& path) { return json::parse(test::ReadFile(path)); }

// The keys of docs/stats.md's "Stats as JSON" table: every `name` in a row's first cell.
// `optional` receives those of rows marked "only".
std::set<std::string> DocumentedKeys(std::set<std::string>* optional) {
  const std::string readme = test::ReadFile(SourcePath("docs/stats.md"));
  const size_t start = readme.find("# Stats as JSON");
  EXPECT_NE(start, std::string::npos) << "docs/stats.md has no \"Stats as JSON\" section";
  const size_t table = readme.find("| key |", start);
  const size_t end = readme.find("\n\n", table);
  std::set<std::string> keys;
  std::istringstream rows(readme.substr(table, end - table));
  const std::regex name("`([a-z_.]+)`");
  for (std::string row; std::getline(rows, row);) {
    if (row.rfind("| `", 0) != 0) continue;
    const std::string first = row.substr(0, row.find(" | ", 2));
    for (std::sregex_iterator it(first.begin(), first.end(), name), stop; it != stop; ++it) {
      keys.insert((*it)[1]);
      if (row.find(" only") != std::string::npos) optional->insert((*it)[1]);
    }
  }
  return keys;
}

// The object's keys, nested objects flattened as "a.b" (but `options`, documented as one).
void CollectKeys(const json& j, const std::string& prefix, std::set<std::string>& keys) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string key = prefix + it.key();
    if (it->is_object() && key != "options") CollectKeys(*it, key + ".", keys);
    else keys.insert(key);
  }
}

TEST(Stats, KeysAreTheReadmeSchemaAndValuesDescribeTheRun) {
  const std::string out = TempPath("stats-cornell.pfm"), stats = TempPath("stats-cornell.json");
  ProcessResult r = Render(kCornell, out, stats, {"--backend", "cpu", "--seed", "7", "--threads", "2"});
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  const json j = ReadJson(stats);

  std::set<std::string> optional;
  const std::set<std::string> documented = DocumentedKeys(&optional);
  std::set<std::string> keys;
  CollectKeys(j, "", keys);
  for (const std::string& k : keys) EXPECT_TRUE(documented.count(k)) << k << " is not in the table of docs/stats.md";
  for (const std::string& k : documented)
    EXPECT_TRUE(keys.count(k) || optional.count(k)) << k << " is documented but missing";
  EXPECT_GT(documented.size(), 40u);

  // Every option is one of vkpt's long options.
  const std::string help = RunVkpt({"--help"}).out;
  for (auto it = j["options"].begin(); it != j["options"].end(); ++it) {
    std::string flag = "--" + it.key();
    std::replace(flag.begin(), flag.end(), '_', '-');
    EXPECT_NE(help.find(flag), std::string::npos) << flag;
  }

  EXPECT_EQ(j["seed"], 7);
  EXPECT_EQ(j["options"]["seed"], 7);
  EXPECT_EQ(j["options"]["threads"], 2);
  EXPECT_TRUE(j["options"]["camera"].is_null());
  EXPECT_EQ(j["width"], 24);
  EXPECT_EQ(j["spp"], 2);
  EXPECT_EQ(j["spp_per_pass"], json::array({1, 1}));  // the first pass measures the rate
  EXPECT_EQ(j["samples"], 2 * 24 * 24);
  EXPECT_EQ(j["stopped_by"], "spp");
  EXPECT_EQ(j["active_pixels"], 24 * 24);
  EXPECT_EQ(j["checkpoints"], 0);
  EXPECT_EQ(j["exit_status"], 0);
  EXPECT_EQ(j["scene"]["triangles"], 32);
  EXPECT_EQ(j["bvh"]["references"], 32);
  EXPECT_EQ(j["device"].get<std::string>().rfind("cpu", 0), 0u) << j["device"];
  EXPECT_TRUE(std::regex_match(j["scene"]["content_hash"].get<std::string>(), std::regex("fnv1a64:[0-9a-f]{16}")));
  EXPECT_GT(j["rays"].get<uint64_t>(), 24u * 24u * 2u);
  const json& t = j["times_s"];
  EXPECT_EQ(t["upload"], 0.0);
  double parts = 0.0;
  for (const char* phase : {"load", "environment", "prepare", "render", "write"}) {
    EXPECT_GE(t[phase].get<double>(), 0.0) << phase;
    parts += t[phase].get<double>();
  }
  EXPECT_LE(parts, t["total"].get<double>());
  EXPECT_NEAR(j["samples_per_s"].get<double>() * t["render"].get<double>(), 24 * 24 * 2, 1e-6);

  // The mean of the image written, to float precision.
  const Image image = ReadPfm(out);
  for (int c = 0; c < 3; ++c) {
    double mean = 0.0;
    for (const glm::vec3& p : image.pixels) mean += p[c];
    mean /= double(image.pixels.size());
    EXPECT_NEAR(j["mean_radiance"][c].get<double>(), mean, 1e-6 * mean) << "channel " << c;
  }
  std::remove(out.c_str());
  std::remove(stats.c_str());
}

TEST(Stats, ContentHashFollowsTheScene) {
  const std::string out = TempPath("stats-hash.png");
  std::vector<std::string> hashes;
  for (const std::string& scene : {kCornell, kCornell, test::SourcePath("scenes/furnace.gltf")}) {
    const std::string stats = TempPath("stats-hash-" + std::to_string(hashes.size()) + ".json");
    ProcessResult r = Render(scene, out, stats, {"--backend", "cpu"});
    ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
    hashes.push_back(ReadJson(stats)["scene"]["content_hash"]);
    std::remove(stats.c_str());
  }
  EXPECT_EQ(hashes[0], hashes[1]);
  EXPECT_NE(hashes[0], hashes[2]);
  std::remove(out.c_str());
}

TEST(Stats, CompareRunNamesBothRenderers) {
  const std::string out = TempPath("stats-compare.png"), stats = TempPath("stats-compare.json");
  ProcessResult r = Render(kCornell, out, stats, {"--compare"});
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  const json j = ReadJson(stats);
  EXPECT_EQ(j["device"].get<std::string>().rfind("vulkan", 0), 0u) << j["device"];
  EXPECT_GT(j["times_s"]["upload"].get<double>(), 0.0);
  EXPECT_EQ(j["compare_reference"]["device"].get<std::string>().rfind("cpu", 0), 0u);
  EXPECT_TRUE(j["options"]["compare"].get<bool>());
  for (const std::string& f : {out, stats, TempPath("stats-compare-diff.png")}) std::remove(f.c_str());
}

TEST(Stats, FailedRunsWriteNoStats) {
  const std::string out = TempPath("stats-fail.png"), stats = TempPath("stats-fail.json");
  {  // a scene that does not exist
    ProcessResult r = Render(TempPath("no-such-scene.gltf"), out, stats, {"--backend", "cpu"});
    EXPECT_TRUE(r.ExitedWith(1)) << r.Describe();
    EXPECT_FALSE(fs::exists(stats));
    EXPECT_FALSE(fs::exists(out));
  }
  {  // a stats file in a folder that does not exist: refused before rendering
    ProcessResult r = Render(kCornell, out, TempPath("no-such-dir/stats.json"), {"--backend", "cpu"});
    EXPECT_TRUE(r.ExitedWith(1)) << r.Describe();
    EXPECT_NE(r.err.find("no-such-dir/stats.json: directory"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
  {  // usage errors
    EXPECT_TRUE(Render(kCornell, out, out).ExitedWith(2));
    EXPECT_TRUE(RunVkpt({"--diff", out, out, "--stats", stats}).ExitedWith(2));
    EXPECT_TRUE(RunVkpt({"--scene", kCornell, "--stats", ""}).ExitedWith(2));
  }
  EXPECT_FALSE(fs::exists(stats));
}

}  // namespace
}  // namespace vkpt::internal

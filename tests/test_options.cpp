// ParseOptions and the "options" object of --stats in process (no subprocess): the
// object keeps its keys and values for every kind of option.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/options.h"
#include "app/run_stats.h"

namespace vkpt {
namespace {

using nlohmann::json;

Options Parse(std::vector<std::string> args) {
  args.insert(args.begin(), "vkpt");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  return ParseOptions(int(argv.size()), argv.data());
}

json StatsOptions(const std::vector<std::string>& args) { return json::parse(OptionsAsJson(Parse(args))); }

TEST(Options, StatsObjectOfTheDefaults) {
  EXPECT_EQ(StatsOptions({"--scene", "dir/box.gltf"}), json::parse(R"({
    "scene": "dir/box.gltf", "out": "box.png", "width": null, "height": null, "spp": 64, "time": null,
    "noise_target": null, "adaptive": false, "checkpoint": null, "seed": 0, "chunk": 16, "max_depth": 32,
    "rr_depth": 3, "backend": "auto", "device": "", "threads": 0, "batch": 0, "compare": false,
    "validation": false, "camera": null, "exposure": 0, "background": null, "env": "", "env_rotation": 0,
    "env_intensity": 1, "texture_lod": "cones", "leaf_size": 8, "splits": "auto", "max_memory": 0,
    "max_texels": 0, "allow_external_uris": false, "aov": [], "denoise": false, "stats": "",
    "verbose": false})"));
}

TEST(Options, StatsObjectOfEveryOptionGiven) {
  // Every option that has a value in the stats, given (split at spaces).
  std::vector<std::string> args;
  std::istringstream words(
      "--scene s.glb --out x.exr --width 10 --height 20 --spp 5 --time 2.5 --noise-target 0.01 --checkpoint 3 --seed 9 "
      "--chunk 8 --max-depth 4 --rr-depth 2 --backend cpu --device lav --threads 3 --batch 7 --validation --camera 1 "
      "--exposure 0.1 --env e.hdr --env-rotation 90 --env-intensity 2 --texture-lod none --leaf-size 4 --splits "
      "spatial --max-memory 64M --max-texels 1K --allow-external-uris --aov normal,depth,normal --denoise --stats "
      "s.json -v --no-adaptive");
  for (std::string w; words >> w;) args.push_back(w);
  EXPECT_EQ(StatsOptions(args), json::parse(R"({
    "scene": "s.glb", "out": "x.exr", "width": 10, "height": 20, "spp": 5, "time": 2.5,
    "noise_target": 0.01, "adaptive": false, "checkpoint": 3, "seed": 9, "chunk": 8, "max_depth": 4,
    "rr_depth": 2, "backend": "cpu", "device": "lav", "threads": 3, "batch": 7, "compare": false,
    "validation": true, "camera": 1, "exposure": 0.10000000149011612, "background": null, "env": "e.hdr",
    "env_rotation": 90, "env_intensity": 2, "texture_lod": "none", "leaf_size": 4, "splits": "spatial",
    "max_memory": 67108864, "max_texels": 1024, "allow_external_uris": true, "aov": ["normal", "depth"],
    "denoise": true, "stats": "s.json", "verbose": true})"));
}

TEST(Options, StatsObjectOfBackgroundCompareAndBudgets) {
  json j = StatsOptions(
      {"--scene", "s.gltf", "--background", "0.25,0.5,1", "--compare", "--splits", "object", "--backend=auto"});
  EXPECT_EQ(j["background"], json::parse("[0.25, 0.5, 1]"));
  EXPECT_EQ(j["compare"], true);
  EXPECT_EQ(j["splits"], "object");
  EXPECT_EQ(StatsOptions({"--scene", "s", "--aov=all"})["aov"],
            json::parse(R"(["albedo", "normal", "depth", "position", "variance", "spp", "heatmap"])"));
  EXPECT_EQ(StatsOptions({"--scene", "s", "--background", "2"})["background"], json::parse("[2, 2, 2]"));
  j = StatsOptions({"--scene", "s", "--noise-target", "1e-3"});
  EXPECT_EQ(j["adaptive"], true);
  EXPECT_EQ(j["spp"], 65536);
  EXPECT_EQ(StatsOptions({"--scene", "s", "--time", "1", "--spp", "9"})["spp"], 9);
  EXPECT_EQ(StatsOptions({"--scene", "s", "--adaptive"})["adaptive"], true);
  EXPECT_EQ(StatsOptions({"--scene", "s", "--backend", "vulkan"})["backend"], "vulkan");
}

}  // namespace
}  // namespace vkpt

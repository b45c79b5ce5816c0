// The options in process (no subprocess): the "options" object of --stats keeps its keys
// and values for every kind of option; the table of docs/options.md is the option table
// (app/option_table.cpp), and a table altered in any way is caught; --help lists the
// table; usage errors show ranges as people write them.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/option_table.h"
#include "app/options.h"
#include "app/run_stats.h"
#include "test_util.h"

namespace vkpt::internal {
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
    "validation": false, "camera": null, "look_from": null, "look_at": null, "up": null, "fov": null,
    "orbit": 0, "exposure": 0, "background": null, "env": "", "env_rotation": 0,
    "env_intensity": 1, "texture_lod": "cones", "light_sampler": "auto", "leaf_size": 8, "splits": "auto", "max_memory": 0,
    "max_texels": 0, "allow_external_uris": false, "aov": [], "denoise": false, "stats": "",
    "variant": "", "animation": "", "at": 0, "frames": null, "fps": 24, "verbose": false, "view": "neutral"})"));
}

TEST(Options, StatsObjectOfEveryOptionGiven) {
  // Every option that has a value in the stats, given (split at spaces).
  std::vector<std::string> args;
  std::istringstream words(
      "--scene s.glb --out x.exr --width 10 --height 20 --spp 5 --time 2.5 --noise-target 0.01 --checkpoint 3 --seed 9 "
      "--chunk 8 --max-depth 4 --rr-depth 2 --backend cpu --device lav --threads 3 --batch 7 --validation --camera 1 "
      "--look-from 1,2,3 --look-at 0,0.5,-1 --up 0,0,1 --fov 35 --orbit -90 "
      "--exposure 0.1 --view agx --env e.hdr --env-rotation 90 --env-intensity 2 --variant beach --animation Walk --at "
      "0.5 --fps "
      "30 "
      "--texture-lod none --light-sampler power --leaf-size 4 "
      "--splits "
      "spatial --max-memory 64M --max-texels 1K --allow-external-uris --aov normal,depth,normal --denoise --stats "
      "s.json -v --no-adaptive");
  for (std::string w; words >> w;) args.push_back(w);
  EXPECT_EQ(StatsOptions(args), json::parse(R"({
    "scene": "s.glb", "out": "x.exr", "width": 10, "height": 20, "spp": 5, "time": 2.5,
    "noise_target": 0.01, "adaptive": false, "checkpoint": 3, "seed": 9, "chunk": 8, "max_depth": 4,
    "rr_depth": 2, "backend": "cpu", "device": "lav", "threads": 3, "batch": 7, "compare": false,
    "validation": true, "camera": 1, "look_from": [1, 2, 3], "look_at": [0, 0.5, -1], "up": [0, 0, 1],
    "fov": 35, "orbit": -90, "exposure": 0.10000000149011612, "background": null, "env": "e.hdr",
    "env_rotation": 90, "env_intensity": 2, "texture_lod": "none", "light_sampler": "power", "leaf_size": 4, "splits": "spatial",
    "max_memory": 67108864, "max_texels": 1024, "allow_external_uris": true, "aov": ["normal", "depth"],
    "denoise": true, "stats": "s.json", "variant": "beach", "animation": "Walk", "at": 0.5, "fps": 30, "frames": null, "verbose": true, "view": "agx"})"));
}

TEST(Options, StatsObjectOfBackgroundCompareAndBudgets) {
  json j = StatsOptions(
      {"--scene", "s.gltf", "--background", "0.25,0.5,1", "--compare", "--splits", "object", "--backend=auto"});
  EXPECT_EQ(j["background"], json::parse("[0.25, 0.5, 1]"));
  EXPECT_EQ(j["compare"], true);
  EXPECT_EQ(j["splits"], "object");
  EXPECT_EQ(StatsOptions({"--scene", "s", "--aov=all"})["aov"],
            json::parse(R"(["albedo", "normal", "depth", "position", "variance", "spp", "heatmap",
                         "object_id", "material_id", "instance_id"])"));
  EXPECT_EQ(StatsOptions({"--scene", "s", "--background", "2"})["background"], json::parse("[2, 2, 2]"));
  // --frames excludes --at, which the test above gives.
  EXPECT_EQ(StatsOptions({"--scene", "s", "--frames", "2:10:4"})["frames"], json::parse("[2, 10, 4]"));
  j = StatsOptions({"--scene", "s", "--noise-target", "1e-3"});
  EXPECT_EQ(j["adaptive"], true);
  EXPECT_EQ(j["spp"], 65536);
  EXPECT_EQ(StatsOptions({"--scene", "s", "--time", "1", "--spp", "9"})["spp"], 9);
  EXPECT_EQ(StatsOptions({"--scene", "s", "--adaptive"})["adaptive"], true);
  EXPECT_EQ(StatsOptions({"--scene", "s", "--backend", "vulkan"})["backend"], "vulkan");
}

// ---------------------------------------------------------------------------------------
// The option table against docs/options.md, --help and the parser's messages

// The Markdown table of `doc` that starts with "| option |": its lines up to the first
// that is not a table row. Empty if there is none.
std::string TableOf(const std::string& doc) {
  std::istringstream lines(doc);
  std::string line, table;
  bool in = false;
  while (std::getline(lines, line)) {
    if (!in && line.rfind("| option |", 0) == 0) in = true;
    if (in && line.rfind("|", 0) != 0) break;
    if (in) table += line + "\n";
  }
  return table;
}

// Empty if `doc`'s table is the option table; else the first line where they part.
std::string TableMismatch(const std::string& doc) {
  std::istringstream have(TableOf(doc)), want(OptionTableMarkdown());
  std::string h, w;
  for (int line = 1;; ++line) {
    const bool moreHave = bool(std::getline(have, h)), moreWant = bool(std::getline(want, w));
    if (!moreHave && !moreWant) return "";
    if (moreHave != moreWant || h != w)
      return "row " + std::to_string(line) + ": docs/options.md has\n  " + (moreHave ? h : "(nothing)") +
             "\nthe option table (host/app/option_table.cpp) has\n  " + (moreWant ? w : "(nothing)");
  }
}

std::string Replaced(std::string s, const std::string& from, const std::string& to) {
  const size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? s : s.replace(at, from.size(), to);
}

TEST(OptionTable, DocsTableIsTheOptionTable) {
  const std::string doc = test::ReadFile(test::SourcePath("docs/options.md"));
  const std::string mismatch = TableMismatch(doc);
  EXPECT_EQ(mismatch, "") << "docs/options.md's table should be, exactly:\n" << OptionTableMarkdown();
}

// The check has teeth: a default, a meaning, a range changed, a row dropped or added, the
// table missing, all are caught.
TEST(OptionTable, AlteredDocsTablesAreCaught) {
  const std::string doc = test::ReadFile(test::SourcePath("docs/options.md"));
  ASSERT_EQ(TableMismatch(doc), "");
  const std::string row =
      "| `--max-depth N` | maximum number of bounces (0: emission seen directly only) | [0, 1024] | 32 |";
  EXPECT_NE(TableMismatch(Replaced(doc, row, Replaced(row, "| 32 |", "| 33 |"))), "");
  EXPECT_NE(TableMismatch(Replaced(doc, row, Replaced(row, "bounces", "bounce"))), "");
  EXPECT_NE(TableMismatch(Replaced(doc, row, Replaced(row, "[0, 1024]", "[0, 1000]"))), "");
  EXPECT_NE(TableMismatch(Replaced(doc, row + "\n", "")), "");
  EXPECT_NE(TableMismatch(Replaced(doc, row + "\n", row + "\n| `--frobnicate` | | | |\n")), "");
  EXPECT_NE(TableMismatch(Replaced(doc, "| option |", "| Option |")), "");
  const std::string last = "| `--version` | print the version and exit | | |\n";
  EXPECT_NE(TableMismatch(Replaced(doc, last, "")), "");
}

// The usage error of `args` after "--scene s"; "" if they parse.
std::string ErrorOf(std::vector<std::string> args) {
  args.insert(args.begin(), {"--scene", "s.gltf"});
  try {
    Parse(args);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(Options, NumbersAreShownAsPeopleWriteThem) {
  EXPECT_EQ(FormatNumber(0), "0");
  EXPECT_EQ(FormatNumber(1), "1");
  EXPECT_EQ(FormatNumber(0.001), "0.001");
  EXPECT_EQ(FormatNumber(16384), "16384");
  EXPECT_EQ(FormatNumber(4294967295.0), "4294967295");
  EXPECT_EQ(FormatNumber(1e7), "1e+07");
  EXPECT_EQ(FormatNumber(-3600), "-3600");
  EXPECT_EQ(RangeText({1, 15}), "[1, 15]");
  EXPECT_EQ(RangeText({0, 1, true}), "(0, 1]");
  EXPECT_EQ(RangeText({0}), "≥ 0");
  EXPECT_EQ(RangeText({0, INFINITY, true}), "> 0");
}

TEST(Options, RangeErrorsReadAsPeopleWriteThem) {
  EXPECT_EQ(ErrorOf({"--noise-target", "0"}), "--noise-target must be in (0, 1], got 0");
  EXPECT_EQ(ErrorOf({"--noise-target", "1.5"}), "--noise-target must be in (0, 1], got 1.5");
  EXPECT_EQ(ErrorOf({"--env", "e.hdr", "--env-intensity", "-1"}), "--env-intensity must be ≥ 0, got -1");
  EXPECT_EQ(ErrorOf({"--env-intensity", "inf"}), "--env-intensity must be a finite number ≥ 0, got inf");
  EXPECT_EQ(ErrorOf({"--background", "1,-2,3"}), "--background must be ≥ 0, got -2");
  EXPECT_EQ(ErrorOf({"--width", "0"}), "--width must be in [1, 16384], got 0");
  EXPECT_EQ(ErrorOf({"--leaf-size", "16"}), "--leaf-size must be in [1, 15], got 16");
  EXPECT_EQ(ErrorOf({"--time", "0"}), "--time must be in [0.001, 1e+07], got 0");
  EXPECT_EQ(ErrorOf({"--exposure", "nan"}), "--exposure must be in [-64, 64], got nan");
  EXPECT_EQ(ErrorOf({"--spp", "4x"}), "--spp expects a number, got \"4x\"");
  EXPECT_EQ(ErrorOf({"--seed", "-1"}), "--seed expects a number, got \"-1\"");
  EXPECT_EQ(ErrorOf({"--backend", "foo"}), "--backend must be auto, cpu or vulkan, got \"foo\"");
  EXPECT_EQ(ErrorOf({"--splits", "sbvh"}), "--splits must be auto, object or spatial, got \"sbvh\"");
  EXPECT_EQ(ErrorOf({"--texture-lod", "auto"}), "--texture-lod must be cones or none, got \"auto\"");
  EXPECT_EQ(ErrorOf({"--aov", "albedo,glow"}),
            "--aov: unknown AOV \"glow\" (albedo, normal, depth, position, variance, spp, heatmap, object_id, "
            "material_id, instance_id or all)");
  EXPECT_EQ(ErrorOf({"--device", ""}), "--device needs a device index or name");
  EXPECT_EQ(ErrorOf({"--env-intensity", "1e30", "--env", "e.hdr"}), "");
}

TEST(Options, ValuesFollowTheOptionOrItsEqualsSign) {
  EXPECT_EQ(ErrorOf({"--spp"}), "--spp needs a value: --spp N");
  EXPECT_EQ(ErrorOf({"--diff", "a.pfm"}), "--diff needs two values: --diff A B");
  EXPECT_EQ(ErrorOf({"--diff=a.pfm", "b.pfm"}), "--diff needs two values: --diff A B");
  EXPECT_EQ(ErrorOf({"--denoise=yes"}), "--denoise takes no value, got \"--denoise=yes\"");
  EXPECT_EQ(ErrorOf({"--frobnicate"}), "unknown option \"--frobnicate\" (see --help)");
  EXPECT_EQ(Parse({"--diff", "a.pfm", "b.pfm"}).diff, (std::vector<std::string>{"a.pfm", "b.pfm"}));
  EXPECT_EQ(Parse({"--scene=x.glb", "--spp=3", "-v"}).api.render.spp, 3u);
}

// --help lists every option of the table with its values and default, within 92 columns.
TEST(Options, HelpIsTheTable) {
  const std::string help = HelpText();
  for (const OptionDef& def : OptionTable()) EXPECT_NE(help.find("  " + def.Synopsis()), std::string::npos);
  EXPECT_NE(help.find("(values: [1, 15]) [default: 8]"), std::string::npos) << help;
  EXPECT_NE(help.find("(values: auto, cpu, vulkan) [default: auto]"), std::string::npos) << help;
  EXPECT_EQ(help.find('`'), std::string::npos) << help;
  std::istringstream lines(help);
  for (std::string line; std::getline(lines, line);) EXPECT_LE(line.size(), 92u) << line;
}

// A default the table shows as a number, or as "off", is what an unset option has.
TEST(Options, DefaultsShownAreTheDefaults) {
  const Options o = Parse({"--scene", "s.gltf"});
  int checked = 0;
  for (const OptionDef& def : OptionTable()) {
    if (!def.how.json) continue;
    const std::string value = def.how.json(o);
    const bool number =
        !def.defaultText.empty() && def.defaultText.find_first_not_of("0123456789.") == std::string::npos;
    const bool choice = def.how.accepts.find("`" + def.defaultText + "`") != std::string::npos;
    std::string want;
    if (number && value != "null") want = def.defaultText;
    else if (def.defaultText == "off") want = "false";
    else if (choice) want = "\"" + def.defaultText + "\"";
    else continue;
    EXPECT_EQ(value, want) << def.LongName();
    ++checked;
  }
  EXPECT_GE(checked, 14);
}

}  // namespace
}  // namespace vkpt::internal

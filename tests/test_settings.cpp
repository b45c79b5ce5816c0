// The settings schema (vkpt/settings_schema.h) walked setting by setting: every value out
// of a setting's range is refused by the command line and by the C++ library with the
// same range in the message, each in its own terms; the command line's defaults are the
// library's. (tests/python/test_settings.py walks the same table for Python.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app/options.h"
#include "app/scene_client.h"
#include "test_util.h"
#include "vkpt/api_terms.h"
#include "vkpt/settings_schema.h"

namespace vkpt::internal {
namespace {

const std::string kCornell = test::SourcePath("scenes/cornell.gltf");

// Values outside `r` (by a step a float still tells apart), and the non-finite ones.
std::vector<double> Outside(const Range& r) {
  std::vector<double> v = {r.loOpen ? r.lo : r.lo - std::max(1.0, std::abs(r.lo) * 1e-3), NAN, INFINITY, -INFINITY};
  if (!std::isinf(r.hi)) v.push_back(r.hi + std::max(1.0, std::abs(r.hi) * 1e-3));
  return v;
}

// The command-line text of v for `setting`: three numbers for a point.
std::string CliText(const Setting& setting, double v) {
  const std::string n = std::isnan(v) ? "nan" : FormatNumber(v);
  const bool point = setting.flag == "--look-from" || setting.flag == "--look-at" || setting.flag == "--up";
  return point ? n + "," + n + "," + n : n;
}

std::string CliError(std::vector<std::string> args) {
  args.insert(args.begin(), {"vkpt", "--scene", kCornell});
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  try {
    ParseOptions(int(argv.size()), argv.data());
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(accepted)";
}

// The library's refusal of `s`: the scene's options at the load, a view's at the render.
std::string ApiError(const ApiSettings& s) {
  vkpt::SceneOptions cpu = s.scene;
  cpu.backend = vkpt::Backend::Cpu;
  try {
    vkpt::Scene scene(kCornell, cpu);
    scene.Render(s.camera, s.render);
  } catch (const vkpt::SettingError& e) {
    return e.what();
  } catch (const vkpt::Error& e) {
    return std::string("not a SettingError: ") + e.what();
  }
  return "(accepted)";
}

// A view that renders at most one small pass should the library accept what it must refuse.
ApiSettings Small() {
  ApiSettings s;
  s.render.width = s.render.height = 8;
  s.render.cancel = [] { return true; };
  return s;
}

TEST(Settings, EveryValueOutOfRangeIsRefusedByTheCommandLineAndTheLibrary) {
  int tried = 0;
  for (const Setting& setting : Settings()) {
    if (!setting.range) continue;
    const std::string range = RangeText(*setting.range);
    for (double v : Outside(*setting.range)) {
      ApiSettings s = Small();
      if (!setting.set(s, v)) continue;  // its type cannot hold v (a negative count)
      ++tried;
      const std::string cli = CliError({setting.flag, CliText(setting, v)});
      EXPECT_NE(cli.find(setting.flag), std::string::npos) << cli;
      EXPECT_NE(cli.find(range), std::string::npos) << setting.flag << " " << v << ": " << cli;
      const std::string api = ApiError(s);
      EXPECT_EQ(api.rfind(setting.field + " must be ", 0), 0u) << setting.key << " = " << v << ": " << api;
      EXPECT_NE(api.find(range), std::string::npos) << setting.key << " = " << v << ": " << api;
    }
  }
  EXPECT_GE(tried, 50);  // 57 when written
}

TEST(Settings, EveryNumberOfTheLibraryHasARange) {
  ApiSettings defaults;
  for (const Setting& setting : Settings()) {
    ApiSettings s;
    const bool number = setting.set(s, 1.0);
    EXPECT_EQ(number, setting.range.has_value()) << setting.key;
    if (!setting.range) continue;
    for (double v : setting.numbers(defaults)) EXPECT_TRUE(setting.range->Holds(v)) << setting.key << " default";
  }
}

TEST(Settings, TheCommandLinesDefaultsAreTheLibrarys) {
  const char* argv[] = {"vkpt", "--scene", "s.gltf"};
  const ApiSettings cli = ParseOptions(3, argv).api;
  const ApiSettings library;
  int compared = 0;
  for (const Setting& setting : Settings()) {
    const std::vector<double> given = setting.numbers(library);
    if (given.empty()) continue;  // absent in the library: each front end's own rule (spp)
    EXPECT_EQ(setting.numbers(cli), given) << setting.flag << " defaults differ from " << setting.field;
    ++compared;
  }
  EXPECT_GE(compared, 8);
}

TEST(Settings, SettingsAtOddsAreRefusedByBoth) {
  ApiSettings timeAlone = Small();
  timeAlone.render.time = 1.0;
  EXPECT_EQ(ApiError(timeAlone), "RenderOptions::time needs SceneOptions::animation: it is a time in that animation");
  EXPECT_EQ(CliError({"--at", "1"}), kTimeWithoutAnimation);

  ApiSettings intensityAlone = Small();
  intensityAlone.scene.environmentIntensity = 2.0f;
  EXPECT_NE(ApiError(intensityAlone).find("SceneOptions::environmentIntensity need SceneOptions::environment"),
            std::string::npos)
      << ApiError(intensityAlone);
  EXPECT_EQ(CliError({"--env-intensity", "2"}), kEnvironmentTermsWithoutEnvironment);
  EXPECT_EQ(CliError({"--env", "e.hdr", "--background", "0"}), kEnvironmentAndBackground);
}

TEST(Settings, MessagesNameEachSettingInTheCallersTerms) {
  for (const Setting& s : Settings()) {
    EXPECT_EQ(InApiTerms(s.flag + " must be"), s.field + " must be");
    EXPECT_EQ(InTerms(s.field + " must be", Terms::kCpp, Terms::kPython), s.PythonName() + " must be");
  }
}

}  // namespace
}  // namespace vkpt::internal

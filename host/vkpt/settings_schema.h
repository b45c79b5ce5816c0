// The settings of the library, each declared once (settings_schema.cpp): how the command
// line, C++ and Python spell it, the numbers it accepts, what it does, and where it lives
// in the public structs. The command line's parser takes its ranges from here, the library checks every
// render's settings against them (CheckSettings), messages are put in each front end's
// terms from the spellings here (vkpt/api_terms.h), and the tests walk the table to try
// every setting out of range in every front end.
#pragma once

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "util/error.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal {

// Numbers from lo to hi; hi infinite: no upper bound (but the number must be finite);
// loOpen: lo itself excluded.
struct Range {
  double lo;
  double hi = INFINITY;
  bool loOpen = false;
  bool Holds(double v) const { return (loOpen ? v > lo : v >= lo) && v <= hi && std::isfinite(v); }
};

// The shortest text that reads back as v: 0.001, 16384, 4294967295, 1e+07, 1e-09.
std::string FormatNumber(double v);
// "[1, 16384]", "(0, 1]", "≥ 0", "> 0": what "must be ..." completes.
std::string RangeText(const Range& r);
// "--fov must be in (0, 179], got 200", "--env-intensity must be a finite number ≥ 0, got
// inf": `name` and `got` (the text of v) as given.
std::string OutOfRange(const std::string& name, const Range& r, double v, const std::string& got);

// The type of a field's value, whether or not the field is optional.
template <class T>
struct ValueOf {
  using type = T;
};
template <class T>
struct ValueOf<std::optional<T>> {
  using type = T;
};

// What one program asks of the library: a scene's options, a view and its render's options.
struct ApiSettings {
  vkpt::SceneOptions scene;
  vkpt::Camera camera;
  vkpt::RenderOptions render;
};

// The parts of ApiSettings, for the tables that name a setting by its part and member
// (settings_schema.cpp, the command line's option table).
inline constexpr auto kScenePart = &ApiSettings::scene;
inline constexpr auto kCameraPart = &ApiSettings::camera;
inline constexpr auto kRenderPart = &ApiSettings::render;

struct Setting {
  std::string key;    // the Python keyword and the --stats key: "max_depth"
  std::string flag;   // the command line's option: "--max-depth"
  std::string field;  // the C++ field: "RenderOptions::maxDepth"
  // Its type: "count" (an unsigned integer), "number", "triple" (three numbers), "flag",
  // "text", "choice" or "list" (of names).
  std::string type;
  // A number (or each of three) in `range`; none: the setting is not a number.
  std::optional<Range> range;
  // The setting's numbers in `s`: none when it is absent or not a number.
  std::function<std::vector<double>(const ApiSettings& s)> numbers;
  // Sets the setting (each of its numbers) to v, for tests that try every value; false if
  // its type cannot hold v (a negative count, a NaN count) or it is not a number.
  std::function<bool(ApiSettings& s, double v)> set;
  // What it does, in one line of the command line's terms (InTerms puts it in another's):
  // the meaning column of --help and docs/options.md, and the Python docstrings' line.
  std::string doc;

  std::string PythonName() const;  // "max_depth"; a camera's: "Camera.fov"
};

// Every setting of SceneOptions, Camera and RenderOptions.
const std::vector<Setting>& Settings();
// The setting of `key`; throws std::out_of_range naming it if there is none.
const Setting& SettingOf(const std::string& key);

// A setting out of its range or at odds with another.
class SettingError : public Error {
 public:
  using Error::Error;
};

// A time is a pose in the chosen animation: without one, only 0 means anything.
inline bool TimeWithoutAnimation(double time, bool animated) { return time != 0.0 && !animated; }

// Settings at odds with each other, in the command line's terms.
inline constexpr const char* kTimeWithoutAnimation = "--at needs --animation: it is a time in that animation";
inline constexpr const char* kEnvironmentAndBackground = "--env and --background both set the environment; give one";
inline constexpr const char* kEnvironmentTermsWithoutEnvironment =
    "--env-rotation and --env-intensity need --env: they turn and scale its map";

// Throws SettingError, in the command line's terms, for the first setting out of its range
// or at odds with another (a time without an animation, an environment's rotation without
// an environment).
void CheckSettings(const ApiSettings& s);

}  // namespace vkpt::internal

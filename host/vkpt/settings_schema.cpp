#include "vkpt/settings_schema.h"

#include <array>
#include <charconv>
#include <limits>
#include <stdexcept>
#include <type_traits>

namespace vkpt::internal {

std::string FormatNumber(double v) {
  char text[32];
  auto [end, ec] = std::to_chars(text, text + sizeof text, v);
  return ec == std::errc() ? std::string(text, end) : std::string("?");
}

std::string RangeText(const Range& r) {
  // Built by constructors and appends: GCC 12 warns of a false -Wrestrict (PR 105651) in
  // a literal assigned or prepended to a string.
  if (std::isinf(r.hi)) return std::string(r.loOpen ? "> " : "≥ ").append(FormatNumber(r.lo));
  return std::string(r.loOpen ? "(" : "[")
      .append(FormatNumber(r.lo))
      .append(", ")
      .append(FormatNumber(r.hi))
      .append("]");
}

std::string OutOfRange(const std::string& name, const Range& r, double v, const std::string& got) {
  const char* what = !std::isinf(r.hi) ? "in " : std::isfinite(v) ? "" : "a finite number ";
  return name + " must be " + what + RangeText(r) + ", got " + got;
}

namespace {

// A field's numbers, and setting them, by its type (three numbers declared first, so that
// the templates below see them).
std::vector<double> NumbersOf(const std::array<float, 3>& v) { return {v[0], v[1], v[2]}; }
bool Assign(std::array<float, 3>& field, double v) {
  field = {float(v), float(v), float(v)};
  return true;
}
template <class T>
std::vector<double> NumbersOf(const T& v) {
  if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) return {double(v)};
  return {};
}
template <class T>
std::vector<double> NumbersOf(const std::optional<T>& v) {
  return v ? NumbersOf(*v) : std::vector<double>{};
}

template <class T>
bool Assign(T& field, double v) {
  if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
    // A count holds only whole numbers in its type's range.
    if (std::is_integral_v<T> && !(v >= 0.0 && v <= double(std::numeric_limits<T>::max()) && v == std::floor(v)))
      return false;
    field = T(v);
    return true;
  }
  return false;
}
template <class T>
bool Assign(std::optional<T>& field, double v) {
  T value{};
  if (!Assign(value, v)) return false;
  field = value;
  return true;
}

template <class T>
std::string TypeOf() {
  if constexpr (std::is_same_v<T, bool>) return "flag";
  if constexpr (std::is_integral_v<T>) return "count";
  if constexpr (std::is_floating_point_v<T>) return "number";
  if constexpr (std::is_enum_v<T>) return "choice";
  if constexpr (std::is_same_v<T, std::string>) return "text";
  if constexpr (std::is_same_v<T, std::array<float, 3>>) return "triple";
  return "list";
}
// The setting `key` (--flag, Struct::field) of `member` in the part `part` of ApiSettings.
template <class Part, class Field>
Setting Row(std::string key, std::string flag, std::string field, std::optional<Range> range, Part ApiSettings::*part,
            Field Part::*member) {
  return {std::move(key),
          std::move(flag),
          std::move(field),
          TypeOf<typename ValueOf<Field>::type>(),
          range,
          [part, member](const ApiSettings& s) { return NumbersOf(s.*part.*member); },
          [part, member](ApiSettings& s, double v) { return Assign(s.*part.*member, v); }};
}

constexpr double kMaxCount = double(1u << 30);  // spp, chunks, batches
constexpr double kMaxSide = 16384;              // pixels, each side
constexpr Range kTurn{-3600, 3600};             // degrees of a turn: ten full ones either way
constexpr Range kCoordinate{-1e9, 1e9};         // scene units
constexpr Range kRadiance{0.0};                 // a radiance or its scale
using S = vkpt::SceneOptions;
using C = vkpt::Camera;
using R = vkpt::RenderOptions;
constexpr auto kScene = &ApiSettings::scene;
constexpr auto kCamera = &ApiSettings::camera;
constexpr auto kRender = &ApiSettings::render;

std::vector<Setting> SceneRows() {
  return {
      Row("backend", "--backend", "SceneOptions::backend", {}, kScene, &S::backend),
      Row("device", "--device", "SceneOptions::device", {}, kScene, &S::device),
      Row("validation", "--validation", "SceneOptions::validation", {}, kScene, &S::validation),
      Row("threads", "--threads", "SceneOptions::threads", Range{0, 1024}, kScene, &S::threads),
      // Bytes (0: half the RAM): any count, the load refusing a scene that needs more.
      Row("max_memory", "--max-memory", "SceneOptions::maxMemory", Range{0, 18446744073709551615.0}, kScene,
          &S::maxMemory),
      Row("max_texels", "--max-texels", "SceneOptions::maxTexels", Range{0, double(1u << 31)}, kScene, &S::maxTexels),
      Row("allow_external_uris", "--allow-external-uris", "SceneOptions::allowExternalUris", {}, kScene,
          &S::allowExternalUris),
      Row("variant", "--variant", "SceneOptions::variant", {}, kScene, &S::variant),
      Row("animation", "--animation", "SceneOptions::animation", {}, kScene, &S::animation),
      Row("environment", "--env", "SceneOptions::environment", {}, kScene, &S::environment),
      Row("environment_intensity", "--env-intensity", "SceneOptions::environmentIntensity", kRadiance, kScene,
          &S::environmentIntensity),
      Row("light_sampler", "--light-sampler", "SceneOptions::lightSampler", {}, kScene, &S::lightSampler),
  };
}

std::vector<Setting> CameraRows() {
  return {
      Row("index", "--camera", "Camera::index", Range{0, 1u << 20}, kCamera, &C::index),
      Row("look_from", "--look-from", "Camera::lookFrom", kCoordinate, kCamera, &C::lookFrom),
      Row("look_at", "--look-at", "Camera::lookAt", kCoordinate, kCamera, &C::lookAt),
      Row("up", "--up", "Camera::up", kCoordinate, kCamera, &C::up),
      Row("fov", "--fov", "Camera::fovDegrees", Range{0.0, 179.0, true}, kCamera, &C::fovDegrees),
      Row("orbit", "--orbit", "Camera::orbitDegrees", kTurn, kCamera, &C::orbitDegrees),
  };
}

std::vector<Setting> RenderRows() {
  return {
      Row("width", "--width", "RenderOptions::width", Range{1, kMaxSide}, kRender, &R::width),
      Row("height", "--height", "RenderOptions::height", Range{1, kMaxSide}, kRender, &R::height),
      Row("spp", "--spp", "RenderOptions::spp", Range{1, kMaxCount}, kRender, &R::spp),
      Row("seconds", "--time", "RenderOptions::seconds", Range{1e-3, 1e7}, kRender, &R::seconds),
      Row("noise_target", "--noise-target", "RenderOptions::noiseTarget", Range{0.0, 1.0, true}, kRender,
          &R::noiseTarget),
      Row("seed", "--seed", "RenderOptions::seed", Range{0, 4294967295.0}, kRender, &R::seed),
      Row("max_depth", "--max-depth", "RenderOptions::maxDepth", Range{0, 1024}, kRender, &R::maxDepth),
      Row("rr_depth", "--rr-depth", "RenderOptions::rrDepth", Range{0, 1024}, kRender, &R::rrDepth),
      Row("chunk_spp", "--chunk", "RenderOptions::chunkSpp", Range{1, kMaxCount}, kRender, &R::chunkSpp),
      Row("batch", "--batch", "RenderOptions::batch", Range{0, kMaxCount}, kRender, &R::batch),
      Row("time", "--at", "RenderOptions::time", Range{0.0, 1e9}, kRender, &R::time),
      Row("background", "--background", "RenderOptions::background", kRadiance, kRender, &R::background),
      Row("environment_rotation", "--env-rotation", "RenderOptions::environmentRotation", kTurn, kRender,
          &R::environmentRotation),
      Row("texture_lod", "--texture-lod", "RenderOptions::textureLod", {}, kRender, &R::textureLod),
      Row("aovs", "--aov", "RenderOptions::aovs", {}, kRender, &R::aovs),
      Row("denoise", "--denoise", "RenderOptions::denoise", {}, kRender, &R::denoise),
  };
}

}  // namespace

std::string Setting::PythonName() const { return field.rfind("Camera::", 0) == 0 ? "Camera." + key : key; }

const std::vector<Setting>& Settings() {
  static const std::vector<Setting> table = [] {
    std::vector<Setting> rows = SceneRows();
    for (auto part : {CameraRows, RenderRows})
      for (Setting& row : part()) rows.push_back(std::move(row));
    return rows;
  }();
  return table;
}

const Setting& SettingOf(const std::string& key) {
  for (const Setting& s : Settings())
    if (s.key == key) return s;
  throw std::out_of_range("no setting \"" + key + "\"");
}

void CheckSettings(const ApiSettings& s) {
  for (const Setting& setting : Settings())
    for (double v : setting.numbers(s))
      if (setting.range && !setting.range->Holds(v))
        throw SettingError(OutOfRange(setting.flag, *setting.range, v, FormatNumber(v)));
  if (s.render.time != 0.0 && s.scene.animation.empty()) throw SettingError(kTimeWithoutAnimation);
  if (!s.scene.environment.empty() && s.render.background) throw SettingError(kEnvironmentAndBackground);
  if (s.scene.environment.empty() && (s.render.environmentRotation != 0.0f || s.scene.environmentIntensity != 1.0f))
    throw SettingError(kEnvironmentTermsWithoutEnvironment);
}

}  // namespace vkpt::internal

#include "vkpt/settings_schema.h"

#include <array>
#include <charconv>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "engine/settings.h"

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
            Field Part::*member, std::string doc) {
  return {std::move(key),
          std::move(flag),
          std::move(field),
          TypeOf<typename ValueOf<Field>::type>(),
          range,
          [part, member](const ApiSettings& s) { return NumbersOf(s.*part.*member); },
          [part, member](ApiSettings& s, double v) { return Assign(s.*part.*member, v); },
          std::move(doc)};
}

constexpr double kMaxCount = double(1u << 30);  // spp, chunks, batches
constexpr double kMaxSide = kMaxImageSide;      // pixels, each side
constexpr Range kTurn{-3600, 3600};             // degrees of a turn: ten full ones either way
constexpr Range kCoordinate{-1e9, 1e9};         // scene units
constexpr Range kRadiance{0.0};                 // a radiance or its scale
using S = vkpt::SceneOptions;
using C = vkpt::Camera;
using R = vkpt::RenderOptions;

std::vector<Setting> SceneRows() {
  return {
      Row("backend", "--backend", "SceneOptions::backend", {}, kScenePart, &S::backend,
          "renderer: `vulkan` (compute shader), `cpu` (reference) or `auto` (vulkan if a device exists)"),
      Row("device", "--device", "SceneOptions::device", {}, kScenePart, &S::device,
          "Vulkan device by index or name substring"),
      Row("validation", "--validation", "SceneOptions::validation", {}, kScenePart, &S::validation,
          "Vulkan validation layer (also `VKPT_VALIDATION=1`); any message: exit status 3"),
      Row("threads", "--threads", "SceneOptions::threads", Range{0, 1024}, kScenePart, &S::threads,
          "CPU threads (0: all cores); also `LP_NUM_THREADS` for lavapipe"),
      // Bytes (0: half the RAM): any count, the load refusing a scene that needs more.
      Row("max_memory", "--max-memory", "SceneOptions::maxMemory", Range{0, 18446744073709551615.0}, kScenePart,
          &S::maxMemory, "host memory a scene may need, checked before it is read"),
      Row("max_texels", "--max-texels", "SceneOptions::maxTexels", Range{0, double(1u << 31)}, kScenePart,
          &S::maxTexels, "texels the scene's texture images may have, checked from their headers"),
      Row("allow_external_uris", "--allow-external-uris", "SceneOptions::allowExternalUris", {}, kScenePart,
          &S::allowExternalUris, "let a glTF read files outside its own folder"),
      Row("variant", "--variant", "SceneOptions::variant", {}, kScenePart, &S::variant,
          "render the materials of this KHR_materials_variants variant"),
      Row("animation", "--animation", "SceneOptions::animation", {}, kScenePart, &S::animation,
          "pose the scene by this glTF animation"),
      Row("environment", "--env", "SceneOptions::environment", {}, kScenePart, &S::environment,
          "equirectangular environment map, `.hdr` or `.exr`, lighting the scene instead of a background"),
      Row("environment_intensity", "--env-intensity", "SceneOptions::environmentIntensity", kRadiance, kScenePart,
          &S::environmentIntensity, "multiply the environment map's radiance by this"),
      Row("light_sampler", "--light-sampler", "SceneOptions::lightSampler", {}, kScenePart, &S::lightSampler,
          "how light sampling chooses among emissive triangles, point and spot lights: `tree` (by how much each may "
          "light the shading point: a light tree), `power` (by power alone) or `auto` (the tree from 8 such lights "
          "on)"),
  };
}

std::vector<Setting> CameraRows() {
  return {
      Row("index", "--camera", "Camera::index", Range{0, 1u << 20}, kCameraPart, &C::index,
          "glTF camera to render from, in scene order; without one, a camera framing the scene"),
      Row("look_from", "--look-from", "Camera::lookFrom", kCoordinate, kCameraPart, &C::lookFrom,
          "move the camera to this point (scene units)"),
      Row("look_at", "--look-at", "Camera::lookAt", kCoordinate, kCameraPart, &C::lookAt,
          "aim the camera at this point"),
      Row("up", "--up", "Camera::up", kCoordinate, kCameraPart, &C::up, "the direction that is up in the image"),
      Row("fov", "--fov", "Camera::fovDegrees", Range{0.0, 179.0, true}, kCameraPart, &C::fovDegrees,
          "vertical field of view of a perspective camera"),
      Row("orbit", "--orbit", "Camera::orbitDegrees", kTurn, kCameraPart, &C::orbitDegrees,
          "turn the camera about the up axis through `--look-at` (else the scene's centre), counter-clockwise seen "
          "from above"),
  };
}

std::vector<Setting> RenderRows() {
  return {
      Row("width", "--width", "RenderOptions::width", Range{1, kMaxSide}, kRenderPart, &R::width,
          "image width in pixels; give one side and the other follows the camera's aspect ratio"),
      Row("height", "--height", "RenderOptions::height", Range{1, kMaxSide}, kRenderPart, &R::height,
          "image height in pixels"),
      Row("spp", "--spp", "RenderOptions::spp", Range{1, kMaxCount}, kRenderPart, &R::spp,
          "samples per pixel; with `--time` or `--noise-target` the most any pixel takes"),
      Row("seconds", "--time", "RenderOptions::seconds", Range{1e-3, 1e7}, kRenderPart, &R::seconds,
          "render passes until this many seconds of rendering are spent (after loading, BVH build and upload)"),
      Row("noise_target", "--noise-target", "RenderOptions::noiseTarget", Range{0.0, 1.0, true}, kRenderPart,
          &R::noiseTarget, "stop once the image's estimated relMSE is at most this; turns on `--adaptive`"),
      Row("seed", "--seed", "RenderOptions::seed", Range{0, 4294967295.0}, kRenderPart, &R::seed,
          "random seed; same seed and device give a bit-identical image"),
      Row("max_depth", "--max-depth", "RenderOptions::maxDepth", Range{0, 1024}, kRenderPart, &R::maxDepth,
          "maximum number of bounces (0: emission seen directly only)"),
      Row("rr_depth", "--rr-depth", "RenderOptions::rrDepth", Range{0, 1024}, kRenderPart, &R::rrDepth,
          "bounces before Russian roulette starts"),
      Row("chunk_spp", "--chunk", "RenderOptions::chunkSpp", Range{1, kMaxCount}, kRenderPart, &R::chunkSpp,
          "samples per pixel per chunk: the image depends on it, not on passes or MPI ranks"),
      Row("batch", "--batch", "RenderOptions::batch", Range{0, kMaxCount}, kRenderPart, &R::batch,
          "Vulkan: samples per pixel per queue submission (0: automatic)"),
      Row("time", "--at", "RenderOptions::time", Range{0.0, 1e9}, kRenderPart, &R::time,
          "time in the `--animation` at which the scene is posed"),
      Row("background", "--background", "RenderOptions::background", kRadiance, kRenderPart, &R::background,
          "constant environment radiance for rays that leave the scene"),
      Row("environment_rotation", "--env-rotation", "RenderOptions::environmentRotation", kTurn, kRenderPart,
          &R::environmentRotation, "turn the map about +Y, counter-clockwise seen from above"),
      Row("texture_lod", "--texture-lod", "RenderOptions::textureLod", {}, kRenderPart, &R::textureLod,
          "mip levels of colour textures after the camera's hit: by each path's ray cone, or level 0 everywhere"),
      Row("aovs", "--aov", "RenderOptions::aovs", {}, kRenderPart, &R::aovs, "also make these AOVs"),
      Row("denoise", "--denoise", "RenderOptions::denoise", {}, kRenderPart, &R::denoise,
          "filter the image with vkpt's own denoiser and keep the raw image too"),
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
  if (TimeWithoutAnimation(s.render.time.value_or(0.0), !s.scene.animation.empty()))
    throw SettingError(kTimeWithoutAnimation);
  if (!s.scene.environment.empty() && s.render.background) throw SettingError(kEnvironmentAndBackground);
  if (s.scene.environment.empty() &&
      (s.render.environmentRotation.value_or(0.0f) != 0.0f || s.scene.environmentIntensity != 1.0f))
    throw SettingError(kEnvironmentTermsWithoutEnvironment);
}

}  // namespace vkpt::internal

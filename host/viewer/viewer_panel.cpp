#include "viewer/viewer_panel.h"

#include <algorithm>
#include <cstdio>
#include <variant>

#include "vkpt/settings_schema.h"

namespace vkpt::internal {
namespace {

constexpr View kViews[] = {View::kNeutral, View::kAgx, View::kAces, View::kClamp};
constexpr double kExposureStops = 10.0;  // the slider's reach; --exposure takes ±64

// The rows in order; ApplyPanel reads them by these positions.
enum Row : size_t {
  kRate,
  kNoise,
  kEngine,
  kRefused,  // text
  kExposure,
  kView,
  kMaxDepth,
  kDenoise,
  kAov,
  kEnvRotation,
  kEnvIntensity,
  kVariant,
  kAnimation,
  kTime,
  kPlay,
  kRows
};

std::string Line(const char* format, double a, double b = 0.0, double c = 0.0) {
  char text[160];
  std::snprintf(text, sizeof text, format, a, b, c);
  return text;
}

size_t IndexOf(const std::vector<std::string>& names, const std::string& name) {
  const auto at = std::find(names.begin(), names.end(), name);
  return at == names.end() ? 0 : size_t(at - names.begin());
}

std::vector<std::string> WithNone(const char* none, std::vector<std::string> names) {
  names.insert(names.begin(), none);
  return names;
}

std::vector<std::string> AnimationNames(const PanelSettings& s) {
  std::vector<std::string> names;
  for (const vkpt::AnimationInfo& a : s.animations) names.push_back(a.name.empty() ? std::to_string(a.index) : a.name);
  return names;
}

double Duration(const PanelSettings& s) {
  for (const vkpt::AnimationInfo& a : s.animations)
    if (a.name == s.animation || std::to_string(a.index) == s.animation) return a.duration;
  return 0.0;
}

}  // namespace

const std::vector<std::string>& PanelAovs() {
  static const std::vector<std::string> aovs = {"image", "albedo", "normal", "depth", "object_id", "material_id"};
  return aovs;
}

std::vector<PanelRow> PanelRows(const PanelSettings& s, const PanelStats& stats) {
  std::vector<PanelRow> rows(kRows);
  rows[kRate] =
      PanelRow::Text(Line("%.0f of %.0f spp, %.3g Msamples/s", stats.spp, stats.maxSpp, stats.samplesPerSecond * 1e-6));
  rows[kNoise] = PanelRow::Text(Line("%.1f s, estimated relMSE %.3g", stats.seconds, stats.relMse));
  rows[kEngine] = PanelRow::Text(stats.engine);
  rows[kRefused] = PanelRow::Text(stats.refused);
  rows[kExposure] = PanelRow::Slider("exposure", s.display.exposure, -kExposureStops, kExposureStops);
  std::vector<std::string> views;
  for (View v : kViews) views.push_back(ViewName(v));
  rows[kView] = PanelRow::Choice("view", IndexOf(views, ViewName(s.display.view)), views);
  const Range depth = *SettingOf("max_depth").range;
  rows[kMaxDepth] = PanelRow::Slider("max depth", s.maxDepth, depth.lo, std::min(depth.hi, 256.0), true, true);
  rows[kDenoise] = PanelRow::Checkbox("denoise", s.denoise);
  rows[kAov] = PanelRow::Choice("show", s.aov.empty() ? 0 : IndexOf(PanelAovs(), s.aov), PanelAovs());
  if (s.environmentRotation) {
    const Range turn = *SettingOf("environment_rotation").range;
    rows[kEnvRotation] = PanelRow::Slider("environment rotation", *s.environmentRotation, std::max(turn.lo, -180.0),
                                          std::min(turn.hi, 180.0));
    const Range radiance = *SettingOf("environment_intensity").range;
    rows[kEnvIntensity] = PanelRow::Slider("environment intensity", *s.environmentIntensity,
                                           std::max(radiance.lo, 0.01), std::min(radiance.hi, 100.0), false, true);
  }
  if (!s.variants.empty())
    rows[kVariant] = PanelRow::Choice("variant", s.variant.empty() ? 0 : IndexOf(s.variants, s.variant) + 1,
                                      WithNone("(none)", s.variants));
  if (!s.animations.empty()) {
    const std::vector<std::string> names = AnimationNames(s);
    rows[kAnimation] = PanelRow::Choice("animation", s.animation.empty() ? 0 : IndexOf(names, s.animation) + 1,
                                        WithNone("(none)", names));
    if (!s.animation.empty()) {
      rows[kTime] = PanelRow::Slider("time", s.time, 0.0, std::max(Duration(s), 1e-3));
      rows[kPlay] = PanelRow::Button(s.playing ? "pause" : "play");
    }
  }
  return rows;
}

PanelChange ApplyPanel(const std::vector<PanelRow>& rows, PanelSettings& s) {
  PanelChange c;
  if (rows.size() != kRows) return c;
  const auto changed = [&](Row r) { return rows[r].changed; };
  if (changed(kExposure)) s.display.exposure = float(rows[kExposure].value), c.display = true;
  if (changed(kView)) s.display.view = kViews[size_t(rows[kView].value)], c.display = true;
  if (changed(kMaxDepth)) s.maxDepth = uint32_t(rows[kMaxDepth].value), c.render = true;
  if (changed(kDenoise)) s.denoise = rows[kDenoise].value != 0.0, c.render = true;
  if (changed(kAov)) {
    const size_t i = size_t(rows[kAov].value);
    s.aov = i == 0 ? "" : PanelAovs()[i];
    c.render = true;
  }
  if (changed(kEnvRotation)) c.scene["environment/rotation"] = *(s.environmentRotation = rows[kEnvRotation].value);
  if (changed(kEnvIntensity)) c.scene["environment/intensity"] = *(s.environmentIntensity = rows[kEnvIntensity].value);
  if (changed(kVariant)) {
    const size_t i = size_t(rows[kVariant].value);
    c.scene["variant"] = s.variant = i == 0 ? "" : s.variants[i - 1];
  }
  if (changed(kAnimation)) {
    const size_t i = size_t(rows[kAnimation].value);
    c.scene["animation"] = s.animation = i == 0 ? "" : AnimationNames(s)[i - 1];
    c.scene["time"] = s.time = 0.0;
    s.playing = false;
  }
  if (changed(kTime)) c.scene["time"] = s.time = rows[kTime].value, s.playing = false;
  if (changed(kPlay)) s.playing = !s.playing;
  return c;
}

void ReadScene(const vkpt::Scene& scene, PanelSettings& s) {
  const vkpt::ParameterMap p = scene.Parameters();
  const auto number = [&](const char* key) -> std::optional<double> {
    const auto at = p.find(key);
    if (at == p.end()) return std::nullopt;
    return std::get<double>(at->second);
  };
  const auto name = [&](const char* key) {
    const auto at = p.find(key);
    return at == p.end() ? std::string() : std::get<std::string>(at->second);
  };
  s.environmentRotation = number("environment/rotation");
  s.environmentIntensity = number("environment/intensity");
  s.variants = scene.Variants();
  s.variant = name("variant");
  s.animations = scene.Animations();
  s.animation = name("animation");
  s.time = number("time").value_or(0.0);
}

PanelSettings StartPanel(vkpt::Scene& scene, const vkpt::RenderOptions& render, const DisplayTransform& display) {
  vkpt::ParameterMap given;
  const vkpt::ParameterMap p = scene.Parameters();
  if (render.time && p.count("time")) given["time"] = *render.time;
  if (render.environmentRotation && p.count("environment/rotation"))
    given["environment/rotation"] = double(*render.environmentRotation);
  if (!given.empty()) scene.Update(given);
  PanelSettings s;
  s.display = display;
  s.maxDepth = render.maxDepth;
  s.denoise = render.denoise;
  ReadScene(scene, s);
  return s;
}

vkpt::RenderOptions RenderOptionsOf(const vkpt::RenderOptions& render, const PanelSettings& s) {
  vkpt::RenderOptions o = render;
  o.maxDepth = s.maxDepth;
  o.denoise = s.denoise;
  o.aovs.clear();
  if (!s.aov.empty()) o.aovs.push_back(s.aov);
  o.time.reset();
  o.environmentRotation.reset();
  return o;
}

double AdvanceTime(const PanelSettings& s, double dt) {
  const double duration = Duration(s), t = s.time + dt;
  return duration > 0.0 && t <= duration ? t : 0.0;
}

}  // namespace vkpt::internal

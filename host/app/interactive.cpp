#include "app/interactive.h"

#include <algorithm>
#include <cstdio>
#include <set>
#include <vector>

#include "util/graceful_stop.h"
#include "vkpt/settings_schema.h"
#ifdef VKPT_WITH_VIEWER
#include "window/presenter.h"
#endif

namespace vkpt::internal {
namespace {

// `word` as a POSIX shell reads it back: bare when it is plain, else in single quotes.
std::string Quoted(const std::string& word) {
  const bool plain = !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || std::string("-_./,:=+@%").find(c) != std::string::npos;
  });
  if (plain) return word;
  std::string quoted = "'";
  for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// Enough digits that the number reads back as the same float or double.
std::string Exact(float v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", double(v));
  return text;
}
std::string Exact(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}
std::string Exact(const std::array<float, 3>& p) { return Exact(p[0]) + "," + Exact(p[1]) + "," + Exact(p[2]); }

}  // namespace

std::string BatchCommand(const Options& o, const ViewedFrame& frame) {
  const auto flag = [](const char* key) { return SettingOf(key).flag; };
  // Each setting as the frame has it, where it differs from the options': the flag and
  // its values (none: the option left out).
  std::vector<std::pair<std::string, std::vector<std::string>>> set = {{flag("width"), {std::to_string(frame.width)}},
                                                                       {flag("height"), {std::to_string(frame.height)}},
                                                                       {flag("spp"), {std::to_string(frame.spp)}}};
  std::set<std::string> dropped = {"--interactive", "--stats"};
  const auto change = [&](const std::string& name, bool differs, std::vector<std::string> values) {
    if (!differs) return;
    dropped.insert(name);
    if (!values.empty() || name == flag("denoise")) set.emplace_back(name, std::move(values));
  };
  const PanelSettings& p = frame.settings;
  const vkpt::RenderOptions& r = o.api.render;
  change("--view", p.display.view != o.view, {ViewName(p.display.view)});
  change("--exposure", p.display.exposure != o.exposure, {Exact(p.display.exposure)});
  change(flag("max_depth"), p.maxDepth != r.maxDepth, {std::to_string(p.maxDepth)});
  if (p.denoise != r.denoise) {
    dropped.insert(flag("denoise"));
    if (p.denoise) set.emplace_back(flag("denoise"), std::vector<std::string>{});
  }
  change(flag("aovs"), !p.aov.empty(), {p.aov});
  if (p.environmentRotation)
    change(flag("environment_rotation"), float(*p.environmentRotation) != r.environmentRotation.value_or(0.0f),
           {Exact(float(*p.environmentRotation))});
  if (p.environmentIntensity)
    change(flag("environment_intensity"), float(*p.environmentIntensity) != o.api.scene.environmentIntensity,
           {Exact(float(*p.environmentIntensity))});
  change(flag("variant"), p.variant != o.api.scene.variant,
         p.variant.empty() ? std::vector<std::string>{} : std::vector<std::string>{p.variant});
  change(flag("animation"), p.animation != o.api.scene.animation,
         p.animation.empty() ? std::vector<std::string>{} : std::vector<std::string>{p.animation});
  change(flag("time"), p.time != r.time.value_or(0.0),
         p.time == 0.0 ? std::vector<std::string>{} : std::vector<std::string>{Exact(p.time)});
  if (const std::optional<vkpt::Camera>& c = frame.camera) {
    for (const char* key : {"index", "look_from", "look_at", "up", "fov", "orbit"}) dropped.insert(flag(key));
    if (c->index) set.emplace_back(flag("index"), std::vector<std::string>{std::to_string(*c->index)});
    if (c->lookFrom) set.emplace_back(flag("look_from"), std::vector<std::string>{Exact(*c->lookFrom)});
    if (c->lookAt) set.emplace_back(flag("look_at"), std::vector<std::string>{Exact(*c->lookAt)});
    if (c->up) set.emplace_back(flag("up"), std::vector<std::string>{Exact(*c->up)});
    if (c->fovDegrees) set.emplace_back(flag("fov"), std::vector<std::string>{Exact(*c->fovDegrees)});
  }
  std::vector<std::string> words = {"vkpt"};
  const auto add = [&](const std::string& name, const std::vector<std::string>& values) {
    words.push_back(name);
    words.insert(words.end(), values.begin(), values.end());
  };
  for (const auto& [name, values] : o.given)
    if (!dropped.count(name) && name != flag("width") && name != flag("height") && name != flag("spp"))
      add(name, values);
  for (const auto& [name, values] : set) add(name, values);
  std::string line;
  for (const std::string& w : words) {
    if (!line.empty()) line += ' ';
    line += Quoted(w);
  }
  return line;
}

int RunInteractive(const Options& o) {
#ifdef VKPT_WITH_VIEWER
  if (const std::optional<std::string> why = NoDisplayReason()) throw UsageError("--interactive: " + *why);
  ViewerSettings s;
  s.scene = o.scene;
  s.sceneOptions = o.api.scene;
  s.sceneOptions.log = [verbose = o.verbose](vkpt::LogLevel level, const std::string& message) {
    if (level == vkpt::LogLevel::Warning || verbose)
      std::fprintf(stderr, "vkpt: %s%s\n", level == vkpt::LogLevel::Warning ? "warning: " : "", message.c_str());
  };
  s.camera = o.api.camera;
  s.render = o.api.render;
  s.display = o.Display();
  s.savePath = o.out;
  s.batchCommand = [&o](const ViewedFrame& frame) { return BatchCommand(o, frame); };
  const GracefulStop stop;  // Ctrl-C closes the window between frames
  s.stop = [] { return GracefulStop::Arrived(); };
  s.say = [](const std::string& line) {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  };
  return RunViewer(s);
#else
  (void)o;
  throw UsageError("--interactive: this vkpt was built without the viewer (cmake -DVKPT_VIEWER=OFF)");
#endif
}

}  // namespace vkpt::internal

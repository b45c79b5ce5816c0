#include "app/interactive.h"

#include <algorithm>
#include <cstdio>
#include <set>
#include <vector>

#include "util/graceful_stop.h"
#include "vkpt/settings_schema.h"
#ifdef VKPT_WITH_VIEWER
#include "viewer/viewer.h"
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

std::string BatchCommand(const Options& o, const std::optional<vkpt::Camera>& camera, uint32_t spp, uint32_t width,
                         uint32_t height) {
  const auto flag = [](const char* key) { return SettingOf(key).flag; };
  std::set<std::string> replaced = {"--interactive", "--stats", flag("width"), flag("height"), flag("spp")};
  if (camera)
    for (const char* key : {"index", "look_from", "look_at", "up", "fov", "orbit"}) replaced.insert(flag(key));
  std::vector<std::string> words = {"vkpt"};
  for (const auto& [name, values] : o.given) {
    if (replaced.count(name)) continue;
    words.push_back(name);
    words.insert(words.end(), values.begin(), values.end());
  }
  words.insert(words.end(), {flag("width"), std::to_string(width), flag("height"), std::to_string(height), flag("spp"),
                             std::to_string(spp)});
  if (camera && camera->index) words.insert(words.end(), {flag("index"), std::to_string(*camera->index)});
  if (camera && camera->lookFrom) words.insert(words.end(), {flag("look_from"), Exact(*camera->lookFrom)});
  if (camera && camera->lookAt) words.insert(words.end(), {flag("look_at"), Exact(*camera->lookAt)});
  if (camera && camera->up) words.insert(words.end(), {flag("up"), Exact(*camera->up)});
  if (camera && camera->fovDegrees) words.insert(words.end(), {flag("fov"), Exact(*camera->fovDegrees)});
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
  s.batchCommand = [&o](const std::optional<vkpt::Camera>& camera, uint32_t spp, uint32_t width, uint32_t height) {
    return BatchCommand(o, camera, spp, width, height);
  };
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

// --stats FILE.json: one JSON object describing a render, for scripts and CI. The schema
// is docs/stats.md; tests/test_stats.cpp checks it.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/options.h"
#include "render/render_scene.h"
#include "scene/scene.h"
#include "session/render_session.h"

namespace vkpt {

// Wall-clock seconds of each phase of a run.
struct RunTimes {
  double load = 0.0;         // reading and checking the glTF
  double environment = 0.0;  // reading the --env map and building its distribution
  double pose = 0.0;         // posing the scene: animation, skins, morph targets, world-space triangles
  double prepare = 0.0;      // BVH build and the renderers' arrays (includes bvh.build_ms)
  double upload = 0.0;       // Vulkan: the scene into device memory (0 on the CPU)
  double render = 0.0;       // the render itself (--compare: the Vulkan one)
  double aov = 0.0;          // the AOV pass (0 without --aov)
  double denoise = 0.0;      // --denoise: the filter (0 without)
  double write = 0.0;        // encoding and writing --out
  double total = 0.0;        // from start to the stats being written
};

double SecondsSince(std::chrono::steady_clock::time_point t0);

// Times the phases of a run one after another: each Lap is the time since the last.
class PhaseTimer {
 public:
  void Lap(double& seconds) {
    seconds = SecondsSince(last_);
    Restart();
  }
  void Restart() { last_ = std::chrono::steady_clock::now(); }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

struct RunOutcome {
  const Scene& scene;
  const RenderScene& rs;
  const RenderedFrame& frame;
  const RenderedFrame* reference;  // --compare: the CPU render; else null
  RunTimes times;
  uint32_t validationMessages = 0;
  int exitStatus = 0;
  std::vector<std::string> files;  // the image files written, --out first
  uint64_t frameMemory = 0;        // bytes counted for the frame (session/frame_memory.h)
};

std::string StatsJson(const Options& o, const RunOutcome& run);

// The "options" object of the stats alone.
std::string OptionsAsJson(const Options& o);

}  // namespace vkpt

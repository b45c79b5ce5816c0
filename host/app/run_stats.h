// --stats FILE.json: one JSON object describing a render, for scripts and CI. The schema
// is in the README ("Stats as JSON"); tests/test_cli.cpp checks it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/options.h"
#include "app/render_loop.h"
#include "dist/chunk_dealer.h"
#include "image/film.h"
#include "render/render_scene.h"
#include "scene/scene.h"

namespace vkpt {

// Wall-clock seconds of each phase of a run.
struct RunTimes {
  double load = 0.0;         // reading and checking the glTF
  double environment = 0.0;  // reading the --env map and building its distribution
  double prepare = 0.0;      // BVH build and the renderers' arrays (includes bvh.build_ms)
  double upload = 0.0;       // Vulkan: the scene into device memory (0 on the CPU)
  double render = 0.0;       // the render itself (--compare: the Vulkan one)
  double aov = 0.0;          // the AOV pass (0 without --aov)
  double denoise = 0.0;      // --denoise: the filter (0 without)
  double write = 0.0;        // encoding and writing --out
  double total = 0.0;        // from start to the stats being written
};

struct RunOutcome {
  const Scene& scene;
  const RenderScene& rs;
  const RenderResult& result;
  const ProgressiveRender& progressive;
  const RenderResult* reference;  // --compare: the CPU render; else null
  RunTimes times;
  uint32_t validationMessages = 0;
  int exitStatus = 0;
  uint32_t aovSamples = 0;         // --aov: samples per pixel of the AOV pass
  std::vector<std::string> files;  // the image files written, --out first
  std::vector<RankShare> ranks;    // an MPI job's ranks (empty for one process)
};

std::string StatsJson(const Options& o, const RunOutcome& run);

// The "options" object of the stats alone.
std::string OptionsAsJson(const Options& o);

}  // namespace vkpt

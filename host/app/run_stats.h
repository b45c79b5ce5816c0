// --stats FILE.json: one JSON object describing a render, for scripts and CI. The schema
// is docs/stats.md; tests/test_stats.cpp checks it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/options.h"
#include "session/render_session.h"
#include "session/run_times.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal {

struct RunOutcome {
  const vkpt::Scene& scene;
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

}  // namespace vkpt::internal

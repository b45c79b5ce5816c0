// Command-line options of `vkpt`; each is a row of the one option table (app/option_table.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bvh/bvh.h"
#include "image/view_transform.h"
#include "session/budget.h"
#include "vkpt/settings_schema.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal {

// --frames FIRST:LAST[:STEP]: the frame numbers FIRST, FIRST + STEP, … up to LAST.
struct FrameRange {
  uint32_t first = 0, last = 0, step = 1;
};

// What the command line asks: the library's settings as the library takes them (`api`:
// the scene's options, the camera and the render's options, with the library's defaults),
// and what only the command line has.
struct Options {
  std::string scene;
  std::string out;       // default: <scene name>.png in the current directory
  std::string outGiven;  // --out exactly as given ("" when absent)
  ApiSettings api;
  double checkpoint = 0.0;  // --checkpoint: seconds between rewrites of --out (0: none)
  bool listDevices = false;
  bool interactive = false;       // --interactive: a window shows the render as it accumulates
  bool compare = false;           // render on both backends and compare
  std::vector<std::string> diff;  // --diff A.pfm B.pfm: compare two existing images
  float exposure = 0.0f;          // --exposure: stops, PNG only
  View view = View::kNeutral;     // --view: how a PNG shows radiance
  DisplayTransform Display() const { return {view, exposure}; }
  // --frames: a sequence of renders, frame k posed k / --fps seconds into the animation and
  // turned by k × --orbit; each written to FramePath(out, k).
  std::optional<FrameRange> frames;
  double fps = 24.0;
  uint32_t leafSize = 8;
  SplitMode splits = SplitMode::kAuto;  // --splits
  std::string stats;                    // --stats FILE.json: the run described as JSON (app/run_stats.h)
  bool verbose = false;
  bool help = false;
  bool version = false;
  // Each option as given, in order: its long name and its values (the viewer's P prints
  // the batch command that renders its view from them).
  std::vector<std::pair<std::string, std::vector<std::string>>> given;

  // The render's budget, as the library derives it (spp bound included).
  RenderBudget Budget() const {
    const vkpt::RenderOptions& r = api.render;
    return BudgetFor({r.spp, r.seconds, r.noiseTarget, r.adaptive, checkpoint, r.chunkSpp});
  }
};

// Throws UsageError for anything malformed; the message says which option and why.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

Options ParseOptions(int argc, const char* const* argv);
std::string HelpText();

}  // namespace vkpt::internal

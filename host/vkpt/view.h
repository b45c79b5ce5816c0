// A view of a loaded scene as the library renders it, in the engine's types: what a
// client inside vkpt — the command line — adds to the public options (vkpt/vkpt.h), the
// frame begun for a view, and what its render gives back. vkpt/client.h has the functions
// that take and return these; this header stays free of the public API's names, which
// share spellings with the engine's (Scene, Image, Camera, Error).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bvh/bvh.h"
#include "engine/loaded_scene.h"
#include "engine/settings.h"
#include "image/view_transform.h"
#include "session/aov.h"
#include "session/render_session.h"

namespace vkpt::internal {

// Scene settings the command line has and the API does not.
struct ClientScene {
  uint32_t leafSize = 8;                // --leaf-size
  SplitMode splits = SplitMode::kAuto;  // --splits
  bool compare = false;                 // --compare: the CPU's BVH layout beside the device's
  bool once = false;                    // one render: the file's data released after the build
  double time = 0.0;                    // --at: posed at load at the first render's time
  EngineLog log;                        // warnings, notices and the load's -v lines
};

// A render's settings the command line has and the API does not.
struct ClientView {
  std::string name;                // the output file, naming the frame in a refusal ("": the scene's file)
  uint32_t ranks = 1;              // of the MPI job whose chunks rank 0 collects
  bool exrOutput = false;          // the image and its AOV layers go to one EXR (its memory is counted)
  double checkpointSeconds = 0.0;  // --checkpoint: the image so far rewritten this often
  std::string checkpointPath;
  DisplayTransform display;  // of a PNG checkpoint
  EngineLog log;             // warnings about the frame's constants
  // The session's per-pass lines (-v) and its warnings; the progress is RenderOptions'.
  std::function<void(const std::string&)> report, warning;
};

// A view prepared (its camera, size, constants and memory) and its frame begun on the
// scene's backend, the scene uploaded to the device if it was not.
struct BegunView {
  PreparedFrame prepared;
  std::unique_ptr<FrameRenderer> renderer;
  std::vector<Aov> aovs;  // as the options name them
};

// A view's render: the session's frame, its AOV layers and, with an id AOV, the names of
// the ids (JSON).
struct RenderedView {
  RenderedFrame frame;
  std::vector<AovLayer> aovs;
  std::string ids;
  const char* denoiser = "";  // the filter's device ("vulkan" or "cpu")
};

}  // namespace vkpt::internal

// The engine's settings from the command line's options (engine/settings.h), and a frame
// prepared from them on the scene they load.
#pragma once

#include <chrono>
#include <memory>

#include "app/options.h"
#include "engine/loaded_scene.h"

namespace vkpt {

struct Prepared {
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  std::unique_ptr<LoadedScene> loaded;
  PreparedFrame frame;

  const Scene& scene() const { return loaded->scene(); }
  const RenderScene& rs() const { return loaded->Arrays(); }
  RunTimes& times() { return loaded->times; }
};

// `report`: this process prints the load report (-v) and warnings (rank 0 of an MPI job).
// `ranks`: of the MPI job this process deals the chunks of (1: it renders alone).
Prepared Prepare(const Options& o, bool report, uint32_t ranks = 1);

// The next frame of a sequence: the scene posed and the camera placed as the frame's
// options say (--at, --orbit); its arrays built anew if its pose changed.
void PrepareFrame(Prepared& p, const Options& o, bool report, uint32_t ranks = 1);

}  // namespace vkpt

// The command line's scene opened through the library (app/scene_client.h) and a frame
// of its options begun on it.
#pragma once

#include <chrono>
#include <memory>

#include "app/options.h"
#include "app/scene_client.h"
#include "vkpt/client.h"

namespace vkpt::internal {

struct Prepared {
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  std::unique_ptr<SceneClient> client;
  ClientView settings;  // the frame's, beyond the API's render options
  BegunView view;       // the frame: its camera, constants, memory and renderer

  vkpt::Scene& scene() { return client->Public(); }
  RunTimes& times() { return TimesOf(scene()); }
};

// `report`: this process prints the load report (-v) and warnings (rank 0 of an MPI job).
// `ranks`: of the MPI job this process deals the chunks of (1: it renders alone).
Prepared Prepare(const Options& o, bool report, uint32_t ranks = 1);

// The next frame of a sequence: the scene posed and the camera placed as the frame's
// options say (--at, --orbit); its arrays built anew if its pose changed. The last
// frame's device buffers go before the next's are made.
void PrepareFrame(Prepared& p, const Options& o, bool report, uint32_t ranks = 1);

}  // namespace vkpt::internal

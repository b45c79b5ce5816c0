// Everything a render needs, from the options: the scene and its environment map, the
// camera and image size, the Vulkan device (or none), the renderers' arrays and the frame
// constants.
#pragma once

#include <chrono>
#include <memory>

#include "app/options.h"
#include "app/run_stats.h"
#include "render/render_scene.h"
#include "scene/scene.h"
#include "session/frame_memory.h"
#include "shared/layout.h"
#include "vk/context.h"

namespace vkpt {

struct Prepared {
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  RunTimes times;
  Scene scene;
  std::unique_ptr<vk::Context> ctx;  // null: the CPU renders
  RenderScene rs;
  shader::FrameParams params;
  std::vector<MemoryPart> frameParts;  // the frame's memory, per pixel (session/frame_memory.h)
  uint64_t frameMemory = 0;            // and in all, counted against --max-memory
};

// `report`: this process prints the load report (-v) and warnings (rank 0 of an MPI job).
// `ranks`: of the MPI job this process deals the chunks of (1: it renders alone).
Prepared Prepare(const Options& o, bool report, uint32_t ranks = 1);

}  // namespace vkpt

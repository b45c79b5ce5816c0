// Everything a render needs, from the options: the scene and its environment map, the
// camera and image size, the Vulkan device (or none), the renderers' arrays and the frame
// constants.
#pragma once

#include <chrono>
#include <memory>

#include "app/options.h"
#include "app/run_stats.h"
#include "render/environment_map.h"
#include "render/render_scene.h"
#include "scene/gltf_loader.h"
#include "scene/scene.h"
#include "session/frame_memory.h"
#include "shared/layout.h"
#include "vk/context.h"

namespace vkpt {

struct Prepared {
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  RunTimes times;
  std::unique_ptr<GltfAsset> asset;  // read once, posed for each frame
  EnvironmentMap environment;        // --env, kept for the next frame of --frames
  uint64_t environmentBytes = 0;
  std::unique_ptr<vk::Context> ctx;  // null: the CPU renders
  RenderScene rs;
  bool built = false;  // rs holds a posed scene's arrays
  shader::FrameParams params;
  std::vector<MemoryPart> frameParts;  // the frame's memory, per pixel (session/frame_memory.h)
  uint64_t frameMemory = 0;            // and in all, counted against --max-memory

  const Scene& scene() const { return asset->scene(); }
};

// `report`: this process prints the load report (-v) and warnings (rank 0 of an MPI job).
// `ranks`: of the MPI job this process deals the chunks of (1: it renders alone).
Prepared Prepare(const Options& o, bool report, uint32_t ranks = 1);

// The next frame of a sequence: the scene posed and the camera placed as the frame's
// options say (--at, --orbit), its arrays and frame constants built anew.
void PrepareFrame(Prepared& p, const Options& o, bool report, uint32_t ranks = 1);

}  // namespace vkpt

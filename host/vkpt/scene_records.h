// The engine's scene described in the public records of vkpt/scene_info.h: what
// vkpt::Scene's accessors return and what the command line reports (-v, --stats).
#pragma once

#include <cstdint>

#include "engine/loaded_scene.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal {

vkpt::MaterialInfo MaterialInfoOf(const Scene& scene, uint32_t index);
vkpt::CameraInfo CameraInfoOf(const Camera& camera, uint32_t index);
vkpt::NodeInfo NodeInfoOf(const NodeSummary& node, uint32_t index);
vkpt::LightInfo LightInfoOf(const PunctualLight& light, uint32_t index);
// The counts of the scene as loaded, and of its arrays as last built.
vkpt::SceneStats StatsOf(const LoadedScene& loaded);

}  // namespace vkpt::internal

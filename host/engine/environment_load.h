// The environment map of a scene's settings: read, charged to the scene's memory budget,
// and given its sampling distribution.
#pragma once

#include <cstdint>

#include "engine/settings.h"
#include "render/environment_map.h"
#include "scene/scene.h"

namespace vkpt::internal {

// The map of s.env (none if empty). Its file, decoded texels and distribution count
// against the memory limit the scene was loaded under, on top of what the scene used;
// the bytes counted go to *counted.
EnvironmentMap LoadEnvironment(const SceneSettings& s, const Scene& scene, const EngineLog& log, uint64_t* counted);

}  // namespace vkpt::internal

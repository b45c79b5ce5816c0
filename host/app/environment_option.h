// --env: the environment map file read, charged to the scene's memory budget, and given
// its sampling distribution.
#pragma once

#include <cstdint>

#include "app/options.h"
#include "render/environment_map.h"
#include "scene/scene.h"

namespace vkpt {

// The map of o.env (none if empty). Its file, decoded texels and distribution count
// against the --max-memory the scene was loaded under, on top of what the scene used.
// -v prints its size and the distribution's build time; warnings go to stderr. The bytes
// counted for the map go to *counted.
EnvironmentMap LoadEnvironment(const Options& o, const Scene& scene, uint64_t* counted);

}  // namespace vkpt

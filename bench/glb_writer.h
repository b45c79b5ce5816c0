// A Scene as a binary glTF (.glb), for benchmarks of the whole program on scenes of any
// size (`vkpt-bench --procedural N --write-glb FILE`): one non-indexed primitive per
// material (positions only: flat shading, as the procedural scene is), metallic-roughness
// materials with KHR_materials_emissive_strength for emission above 1, and the first
// camera on a node of its own.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace vkpt::internal::bench {

std::vector<uint8_t> EncodeGlb(const Scene& scene);

}  // namespace vkpt::internal::bench

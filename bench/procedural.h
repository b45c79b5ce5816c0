// A deterministic procedural scene of about N triangles for benchmarks: a displaced,
// finely tessellated sphere (half the triangles) standing on a noisy terrain (the other
// half) inside five box walls, lit by one emissive quad. Same N → same triangles.
#pragma once

#include <cstdint>

#include "scene/scene.h"

namespace vkpt::internal::bench {

Scene ProceduralScene(uint32_t triangles);

}  // namespace vkpt::internal::bench

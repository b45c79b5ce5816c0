// The memory a glTF file's meshes will take, counted before any is decoded (spec §3.7):
// each primitive's accessors decoded, a posed copy of the largest morphed or skinned one,
// and every triangle of every instance through to the renderer's arrays.
#pragma once

#include <cstdint>
#include <vector>

#include "gltf/gltf_source.h"
#include "scene/load_limits.h"

namespace vkpt::internal {

// Charges `budget` for the meshes of `src`, each instanced `instances[mesh]` times.
// `textured`, `tangents`: the scene keeps the texture coordinates, the tangents of every
// triangle.
void ChargeGeometry(const GltfSource& src, const std::vector<uint64_t>& instances, bool textured, bool tangents,
                    MemoryBudget& budget);

}  // namespace vkpt::internal

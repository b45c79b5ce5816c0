// glTF materials as shared/bsdf.h renders them: the metallic-roughness factors, emission
// (× KHR_materials_emissive_strength), KHR_materials_ior, KHR_materials_specular,
// KHR_materials_unlit and double-sidedness.
#pragma once

#include <cstdint>

#include "gltf/gltf_source.h"
#include "scene/scene.h"

namespace vkpt::internal {

// Appends every material of the file, then glTF's default material (white, rough,
// one-sided) for primitives that name none; returns the default's index. Factors out of
// their ranges are errors naming the material.
uint32_t LoadMaterials(const GltfSource& src, Scene& scene);

}  // namespace vkpt::internal

// glTF materials as vkpt renders them today: base colour, emission (with
// KHR_materials_emissive_strength), double-sidedness; metallic and roughness are kept.
#pragma once

#include <cstdint>

#include "scene/gltf_source.h"
#include "scene/scene.h"

namespace vkpt {

// Appends every material of the file, then glTF's default material (white, rough,
// one-sided) for primitives that name none; returns the default's index. Factors out of
// their ranges are errors naming the material.
uint32_t LoadMaterials(const GltfSource& src, Scene& scene);

}  // namespace vkpt

// Scene materials (scene/material.h) in the GPU's std430 layout, shader::Material
// (shaders/shared/layout.h), which both renderers read: the glTF switches become flag
// bits, and whether the material has textures is worked out from its texture slots.
#pragma once

#include <vector>

#include "scene/scene.h"
#include "shared/layout.h"

namespace vkpt {

// One material; `textures` are its kTextureSlots TextureRefs, or null when the scene
// has no textures.
shader::Material PackMaterial(const Material& m, const shader::TextureRef* textures);

// Every material of the scene, in order.
std::vector<shader::Material> PackMaterials(const Scene& scene);

}  // namespace vkpt

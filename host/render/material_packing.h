// Scene materials (scene/material.h) in the GPU's std430 layout (shaders/shared/layout.h),
// which both renderers read: shader::Material with the glTF switches as flag bits, and
// the materials' textures as kTextureSlots shader::TextureRefs each.
#pragma once

#include <vector>

#include "scene/scene.h"
#include "shared/layout.h"

namespace vkpt::internal {

struct PackedMaterials {
  std::vector<shader::Material> materials;      // one per Scene material, in order
  std::vector<shader::TextureRef> textureRefs;  // kTextureSlots per material; empty when none has a texture
};

// One material; kMaterialTextured and kMaterialExtensionTextured follow from its textures.
shader::Material PackMaterial(const Material& m);

// Its textures, in slot order (kSlotBaseColor …), appended to `refs`. The shaders decode a
// slot's bytes as the slot's kind, colour or data (shader::kSrgbSlots); a texture of the
// other kind in a slot (not made by the loader, which makes one texture per kind) is
// refused (Error).
void PackTextureRefs(const Material& m, const std::vector<SceneTexture>& textures,
                     std::vector<shader::TextureRef>& refs);

PackedMaterials PackMaterials(const Scene& scene);

}  // namespace vkpt::internal

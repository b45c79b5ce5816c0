// glTF textures (spec §3.8) as the materials use them: each textureInfo becomes a
// MaterialTexture (texture, TEXCOORD set, KHR_texture_transform), each texture a
// SceneTexture with its sampler, each image they need is decoded once. Images are
// untrusted: their size is checked from the header and counted against the texel and
// memory budgets before anything is decoded.
#pragma once

#include <string>

#include "gltf/gltf_source.h"
#include "scene/load_limits.h"
#include "scene/scene.h"

namespace vkpt::internal {

// Fills the materials' textures and normalScale, and scene.textures and images (nothing
// when no material has a texture). `scene.materials` must be loaded, in glTF order.
void LoadTextures(const GltfSource& src, const LoadLimits& limits, MemoryBudget& budget, Scene& scene);

// Whether some material of the loaded scene has a normal texture or is anisotropic (and
// so its triangles need tangents).
bool UsesTangents(const Scene& scene);

// Whether vkpt applies the texture `field` of material extension `extension` (the others
// are listed by -v as ignored).
bool IsAppliedExtensionTexture(const std::string& extension, const std::string& field);

}  // namespace vkpt::internal

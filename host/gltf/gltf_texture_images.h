// The glTF images the materials' textures use, decoded (PNG, JPEG). Images are
// untrusted: every header is read, and its size counted against the texel and memory
// budgets, before the first image is decoded; then they are decoded in parallel.
#pragma once

#include <map>
#include <string>

#include "gltf/gltf_source.h"
#include "scene/load_limits.h"
#include "scene/scene.h"

namespace vkpt::internal {

// Decodes the images of `users` (glTF image → the first textureInfo using it, for
// messages) into scene.images, in glTF order, and points each of scene.textures, whose
// `image` is still a glTF image index, at its entry of scene.images.
void LoadTextureImages(const GltfSource& src, const std::map<int, std::string>& users, const LoadLimits& limits,
                       MemoryBudget& budget, Scene& scene);

}  // namespace vkpt::internal

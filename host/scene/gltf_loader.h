// glTF 2.0 (.gltf / .glb) → Scene.
#pragma once

#include <string>

#include "scene/scene.h"

namespace vkpt {

// Loads the default scene (else scene 0; with no scenes, every root node) of a glTF
// file. Everything the renderer reads is validated first; any problem throws vkpt::Error
// whose message starts with the file name.
Scene LoadGltf(const std::string& path);

}  // namespace vkpt

// glTF 2.0 (.gltf / .glb) → Scene.
#pragma once

#include <string>

#include "scene/load_limits.h"
#include "scene/scene.h"

namespace vkpt {

// Loads the default scene (else scene 0; with no scenes, every root node) of a glTF
// file. Everything the renderer reads is validated first, files are read only as
// `limits` allow (scene/asset_access.h), and the memory the scene will need is counted
// against limits.maxMemory before it is allocated; any problem throws vkpt::Error whose
// message starts with the file name. `variant` names a KHR_materials_variants variant
// (its name or index) whose materials the primitives take; "" keeps their own.
Scene LoadGltf(const std::string& path, const LoadLimits& limits = {}, const std::string& variant = "");

}  // namespace vkpt

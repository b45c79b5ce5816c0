// The camera and image size a render asks for, resolved against the loaded scene.
#pragma once

#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "engine/settings.h"
#include "scene/scene.h"

namespace vkpt::internal {

// The scene's camera `c.index` (or, in a scene without cameras, one framing it) moved by
// look-from, look-at and up, turned by orbit, with the field of view given. Errors name
// `path`, the scene's file.
Camera ChooseCamera(const Scene& scene, const CameraSettings& c, const std::string& path);

// What the picture asks for; a missing side follows the camera's aspect ratio (512 wide
// when neither is given), at least 1. Throws Error naming `path` where that side would be
// beyond kMaxImageSide.
glm::uvec2 ImageSize(const Camera& cam, const PictureSettings& p, const std::string& path);

}  // namespace vkpt::internal

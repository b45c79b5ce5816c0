// KHR_lights_punctual: the lights the file defines, checked against the extension's
// rules, and placed in the world by the nodes that reference them.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "gltf/gltf_source.h"
#include "scene/scene.h"

namespace vkpt::internal {

// Every lights[i], referenced or not: a known type, color three numbers in [0, 1],
// intensity finite and >= 0, range >= 0 (0 = infinite), and for spots
// 0 <= innerConeAngle < outerConeAngle <= π/2.
void CheckLights(const GltfSource& src);

// The light nodes[nodeIndex] references (extensions.KHR_lights_punctual.light), checked
// to be in range; -1 when it has none.
int NodeLight(const GltfSource& src, int nodeIndex);

// lights[lightIndex] at a node's world transform: position from its origin, direction
// its −Z axis normalized (the node's scale shapes neither the light nor its cone).
PunctualLight PlaceLight(const GltfSource& src, int lightIndex, const glm::dmat4& world, const std::string& nodeName);

}  // namespace vkpt::internal

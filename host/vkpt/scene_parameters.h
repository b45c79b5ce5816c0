// A loaded scene's editable values as vkpt::ParameterMap (vkpt/parameters.h): what
// Scene::Parameters() lists and Scene::Update() checks and applies.
#pragma once

#include <string>

#include "engine/loaded_scene.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal {

vkpt::ParameterMap ParametersOf(const LoadedScene& loaded);

// The scene's variant and animation as Parameters() spells them ("": none).
struct ChosenSpellings {
  std::string variant, animation;
};
ChosenSpellings ChoicesOf(const LoadedScene& loaded);

// Checks every change, then applies those that differ from the scene's values (none if a
// change is refused: SettingError naming the key).
void ApplyParameters(LoadedScene& loaded, const vkpt::ParameterMap& changes);

}  // namespace vkpt::internal

// A loaded scene's editable values (Scene::Parameters, Scene::Update), after Mitsuba 3's
// mi.traverse: one map from a path to a value. Standard C++ only; included by vkpt/vkpt.h.
//
//   vkpt::ParameterMap p = scene.Parameters();
//   p["materials/1/base_color"] = vkpt::Rgb{0.8f, 0.1f, 0.1f};
//   p["materials/1/roughness"] = 0.3;
//   scene.Update(p);  // applies what differs; the next Render shows it
#pragma once

#include <map>
#include <string>
#include <variant>

#include "vkpt/scene_info.h"

namespace vkpt {
inline namespace v1 {

// A number, a switch or an RGB triple, as the key's field is.
using ParameterValue = std::variant<double, bool, Rgb>;

// Keys: "materials/<index>/<field>" for every field of VKPT_MATERIAL_FACTORS (its Python
// name: "base_color", "roughness", …), and "environment/intensity" in a scene lit by an
// environment map.
using ParameterMap = std::map<std::string, ParameterValue>;

}  // namespace v1
}  // namespace vkpt

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

// A number, a switch, 3 numbers (an RGB colour, a vector), a rotation or a name, as the
// key's field is.
using ParameterValue = std::variant<double, bool, Vec3, Quat, std::string>;

// Keys, each index the file's (glTF's):
//   "materials/<i>/<field>" for every field of VKPT_MATERIAL_FACTORS (its Python name:
//     "base_color", "roughness", …);
//   "nodes/<i>/translation", "nodes/<i>/rotation" and "nodes/<i>/scale": the node's local
//     transform (NodeInfo);
//   "lights/<i>/color" and "lights/<i>/intensity": KHR_lights_punctual lights[i];
//   "variant" in a file with KHR_materials_variants: the variant rendered, by name (or
//     index), "" for the primitives' own materials;
//   "animation" and "time" in a file with animations: the animation posing the scene, by
//     name (or index; "": none), and the seconds into it of renders that name no
//     RenderOptions::time (not 0 without an animation);
//   "environment/intensity" and "environment/rotation" (degrees about +Y, for renders that
//     name no RenderOptions::environmentRotation) in a scene lit by an environment map.
// A node's and a light's values are checked as the file's are when it loads, a variant
// or an animation as SceneOptions' are.
using ParameterMap = std::map<std::string, ParameterValue>;

}  // namespace v1
}  // namespace vkpt

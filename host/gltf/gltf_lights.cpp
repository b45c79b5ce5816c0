#include "gltf/gltf_lights.h"

#include <cmath>

#include <glm/gtc/constants.hpp>

namespace vkpt::internal {
namespace {

constexpr const char* kExtension = "KHR_lights_punctual";

PunctualLight::Type LightType(const GltfSource& src, const tinygltf::Light& light, const std::string& name) {
  if (light.type == "point") return PunctualLight::Type::kPoint;
  if (light.type == "spot") return PunctualLight::Type::kSpot;
  if (light.type == "directional") return PunctualLight::Type::kDirectional;
  src.Fail(name + ".type \"" + light.type + "\" is not point, spot or directional");
}

}  // namespace

void CheckLights(const GltfSource& src) {
  for (size_t i = 0; i < src.m.lights.size(); ++i) {
    const tinygltf::Light& light = src.m.lights[i];
    const std::string name = "lights[" + std::to_string(i) + "]";
    const PunctualLight::Type type = LightType(src, light, name);
    if (!light.color.empty() && light.color.size() != 3) src.Fail(name + ".color must have 3 numbers");
    for (double c : light.color)
      if (!(c >= 0.0 && c <= 1.0)) src.Fail(name + ".color has " + std::to_string(c) + ", outside [0, 1]");
    if (!(std::isfinite(light.intensity) && light.intensity >= 0.0))
      src.Fail(name + ".intensity must be a finite number >= 0, got " + std::to_string(light.intensity));
    // tinygltf reads an absent range as 0, the extension's "infinite".
    if (!(std::isfinite(light.range) && light.range >= 0.0))
      src.Fail(name + ".range must be a number > 0, got " + std::to_string(light.range));
    if (type != PunctualLight::Type::kSpot) continue;
    const double inner = light.spot.innerConeAngle, outer = light.spot.outerConeAngle;
    if (!(inner >= 0.0 && inner < outer && outer <= glm::half_pi<double>()))
      src.Fail(name + ".spot cone angles must satisfy 0 <= innerConeAngle < outerConeAngle <= π/2, got " +
               std::to_string(inner) + " and " + std::to_string(outer));
  }
}

int NodeLight(const GltfSource& src, int nodeIndex) {
  const tinygltf::Node& node = src.m.nodes[nodeIndex];
  auto ext = node.extensions.find(kExtension);
  if (ext == node.extensions.end()) return -1;
  const std::string name = "nodes[" + std::to_string(nodeIndex) + "].extensions." + kExtension;
  if (!ext->second.IsObject() || !ext->second.Has("light")) src.Fail(name + " must be an object with a light index");
  const tinygltf::Value& index = ext->second.Get("light");
  if (!index.IsInt()) src.Fail(name + ".light must be an integer index");
  src.CheckIndex(index.GetNumberAsInt(), src.m.lights, name + ".light");
  return index.GetNumberAsInt();
}

PunctualLight PlaceLight(const GltfSource& src, int lightIndex, const glm::dmat4& world, const std::string& nodeName) {
  const tinygltf::Light& in = src.m.lights[lightIndex];
  PunctualLight out;
  out.type = LightType(src, in, "lights[" + std::to_string(lightIndex) + "]");
  out.name = in.name.empty() ? nodeName : in.name;
  const glm::dvec3 position(world[3]), direction = -glm::dvec3(world[2]);
  const double length = glm::length(direction);
  if (!(length > 1e-12) || !std::isfinite(length) || !std::isfinite(glm::length(position)) ||
      glm::any(glm::greaterThan(glm::abs(position), glm::dvec3(1e30))))
    src.Fail(nodeName + ": the transform of its light (lights[" + std::to_string(lightIndex) + "]) is degenerate");
  out.position = glm::vec3(position);
  out.direction = glm::vec3(direction / length);
  const glm::dvec3 color = in.color.empty() ? glm::dvec3(1.0) : glm::dvec3(in.color[0], in.color[1], in.color[2]);
  out.intensity = glm::vec3(color * in.intensity);
  out.light = uint32_t(lightIndex);
  out.color = glm::vec3(color);
  out.lightIntensity = float(in.intensity);
  out.range = float(in.range);
  if (out.type == PunctualLight::Type::kSpot) {
    out.cosInner = float(std::cos(in.spot.innerConeAngle));
    out.cosOuter = float(std::cos(in.spot.outerConeAngle));
  }
  return out;
}

}  // namespace vkpt::internal

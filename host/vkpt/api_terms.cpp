#include "vkpt/api_terms.h"

#include <array>
#include <cstddef>

namespace vkpt::internal {
namespace {

// Each setting a message names, spelt as Terms lists them; longest first where one
// spelling begins another's.
constexpr std::array<const char*, 3> kSettings[] = {
    {"--width/--height", "RenderOptions::width/height", "width/height"},
    {"--width and --height", "RenderOptions::width and height", "width and height"},
    {"--backend cpu", "Backend::Cpu", "backend=\"cpu\""},
    {"--max-memory", "SceneOptions::maxMemory", "max_memory"},
    {"--max-texels", "SceneOptions::maxTexels", "max_texels"},
    {"--allow-external-uris", "SceneOptions::allowExternalUris", "allow_external_uris"},
    {"--animation", "SceneOptions::animation", "animation"},
    {"--variant", "SceneOptions::variant", "variant"},
    {"--batch", "RenderOptions::batch", "batch"},
    {"--background", "RenderOptions::background", "background"},
    {"--look-from/--look-at/--up", "Camera::lookFrom/lookAt/up", "Camera.look_from/look_at/up"},
    {"--orbit", "Camera::orbitDegrees", "Camera.orbit"},
    {"(see --list-devices)", "(`vkpt --list-devices` lists them)", "(`vkpt --list-devices` lists them)"},
    {"--device", "SceneOptions::device", "device"},
};

}  // namespace

std::string InTerms(std::string message, Terms from, Terms to) {
  for (const std::array<const char*, 3>& setting : kSettings) {
    const std::string was = setting[size_t(from)], is = setting[size_t(to)];
    for (size_t at = message.find(was); at != std::string::npos; at = message.find(was, at + is.size()))
      message.replace(at, was.size(), is);
  }
  return message;
}

}  // namespace vkpt::internal

#include "vkpt/api_terms.h"

#include <utility>

namespace vkpt {
namespace {

// Longest first where one option's spelling begins another's.
constexpr std::pair<const char*, const char*> kTerms[] = {
    {"--width/--height", "RenderOptions::width/height"},
    {"--width and --height", "RenderOptions::width and height"},
    {"--backend cpu", "Backend::Cpu"},
    {"--max-memory", "SceneOptions::maxMemory"},
    {"--max-texels", "SceneOptions::maxTexels"},
    {"--allow-external-uris", "SceneOptions::allowExternalUris"},
    {"--animation", "SceneOptions::animation"},
    {"--variant", "SceneOptions::variant"},
    {"--batch", "RenderOptions::batch"},
    {"--background", "RenderOptions::background"},
    {"--look-from/--look-at/--up", "Camera::lookFrom/lookAt/up"},
    {"--orbit", "Camera::orbitDegrees"},
    {"(see --list-devices)", "(`vkpt --list-devices` lists them)"},
    {"--device", "SceneOptions::device"},
};

}  // namespace

std::string InApiTerms(std::string message) {
  for (const auto& [option, setting] : kTerms) {
    const std::string from = option, to = setting;
    for (size_t at = message.find(from); at != std::string::npos; at = message.find(from, at + to.size()))
      message.replace(at, from.size(), to);
  }
  return message;
}

}  // namespace vkpt

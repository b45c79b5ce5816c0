#include "vkpt/api_terms.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "vkpt/settings_schema.h"

namespace vkpt::internal {
namespace {

using Spellings = std::array<std::string, 3>;  // in the order of Terms

// Each setting of the schema, and the phrases that name settings otherwise, spelt as Terms
// lists them; longest first in each spelling, so that none replaces the start of a longer
// one ("--env" of "--env-rotation").
std::vector<Spellings> SpellingsByLength(Terms from) {
  std::vector<Spellings> all = {
      {"--width/--height", "RenderOptions::width/height", "width/height"},
      {"--width and --height", "RenderOptions::width and height", "width and height"},
      {"--backend cpu", "Backend::Cpu", "backend=\"cpu\""},
      {"--adaptive", "RenderOptions::adaptive", "adaptive"},
      {"--look-from/--look-at/--up", "Camera::lookFrom/lookAt/up", "Camera.look_from/look_at/up"},
      {"(see --list-devices)", "(`vkpt --list-devices` lists them)", "(`vkpt --list-devices` lists them)"},
  };
  for (const Setting& s : Settings()) all.push_back({s.flag, s.field, s.PythonName()});
  std::stable_sort(all.begin(), all.end(), [from](const Spellings& a, const Spellings& b) {
    return a[size_t(from)].size() > b[size_t(from)].size();
  });
  return all;
}

}  // namespace

std::string InTerms(std::string message, Terms from, Terms to) {
  static const std::array<std::vector<Spellings>, 3> byLength = {
      SpellingsByLength(Terms::kCommandLine), SpellingsByLength(Terms::kCpp), SpellingsByLength(Terms::kPython)};
  for (const Spellings& setting : byLength[size_t(from)]) {
    const std::string& was = setting[size_t(from)];
    const std::string& is = setting[size_t(to)];
    for (size_t at = message.find(was); at != std::string::npos; at = message.find(was, at + is.size()))
      message.replace(at, was.size(), is);
  }
  return message;
}

}  // namespace vkpt::internal

// The engine's messages name the settings by the command line's options (`--max-memory`);
// a C++ program sets them as fields (`SceneOptions::maxMemory`), a Python one as keywords
// (`max_memory`). The settings schema (vkpt/settings_schema.h) spells each setting all
// three ways, and messages leave each front end in its own terms.
#pragma once

#include <string>
#include <utility>

namespace vkpt::internal {

// Who reads a message.
enum class Terms { kCommandLine, kCpp, kPython };

// `message` with every setting it names in `from`'s spelling put in `to`'s.
std::string InTerms(std::string message, Terms from, Terms to);

// The engine's message as the C++ API says it.
inline std::string InApiTerms(std::string message) {
  return InTerms(std::move(message), Terms::kCommandLine, Terms::kCpp);
}

}  // namespace vkpt::internal

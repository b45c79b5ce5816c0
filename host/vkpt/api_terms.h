// The engine's messages name the settings by the command line's options (`--max-memory`);
// a library user set them as fields (`SceneOptions::maxMemory`). Messages leave the API in
// its terms.
#pragma once

#include <string>

namespace vkpt {

// `message` with every command-line option it names replaced by the API's setting.
std::string InApiTerms(std::string message);

}  // namespace vkpt

// Checks of the glTF JSON that tinygltf does not make: it silently maps an index of -1
// to "absent" and skips a non-array where an array is required, so a file with
// `"index": -1` or `"primitives": {}` would load as something its author did not write.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace vkpt::internal {

// Parses the glTF JSON (nesting limited, so neither the parser nor a walk over the tree
// can exhaust the stack); throws Error naming `path` on invalid JSON.
nlohmann::json ParseGltfJson(const std::string& path, std::string_view text);

// Throws Error naming `path` and the JSON location of the first violation.
void CheckGltfSchema(const std::string& path, const nlohmann::json& doc);

}  // namespace vkpt::internal

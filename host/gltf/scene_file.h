// The --scene file itself: refused from its type, its first bytes or its size before it
// is read, then read exactly as far as its format says it extends.
#pragma once

#include <string>
#include <string_view>

#include "scene/load_limits.h"

namespace vkpt::internal {

struct SceneFile {
  std::string bytes;      // the whole file
  bool binary = false;    // GLB container (by its magic, not its name)
  std::string_view json;  // the JSON text: the whole file, or a GLB's JSON chunk
};

// Throws Error naming `path`: not a regular file, empty, neither JSON nor GLB by
// its first bytes, a GLB whose header disagrees with the file's size, or more than
// `budget` can take (the JSON's parse costs a multiple of its size; see the .cpp).
SceneFile ReadSceneFile(const std::string& path, MemoryBudget& budget);

// Puts `json` in place of the file's JSON text: the whole file, or a GLB's JSON chunk
// (padded with spaces, the container's lengths updated, the BIN chunk kept).
void ReplaceJson(SceneFile& file, const std::string& json);

}  // namespace vkpt::internal

// Structural check of a binary glTF (GLB) container before tinygltf parses it.
#pragma once

#include <string>
#include <string_view>

namespace vkpt::internal {

// Validates the 12-byte header and the chunk table of a GLB file (glTF spec §4.4): magic,
// version 2, declared length = file size, JSON first, at most one BIN chunk right after
// it, every chunk 4-byte aligned and inside the file. Returns the JSON chunk's text;
// throws Error naming `path` otherwise.
std::string_view CheckGlbHeader(const std::string& path, std::string_view file);

}  // namespace vkpt::internal

// The EXT_meshopt_compression codec on one stream (meshoptimizer's, glTF extension
// README "Compression modes" and "Filters"): ATTRIBUTES, TRIANGLES and INDICES, then
// the OCTAHEDRAL, QUATERNION and EXPONENTIAL filters. The stream comes from the file, so
// every parameter is checked before meshoptimizer sees it (its decoders assert on a bad
// size or stride) and malformed data is an error, never a read out of bounds.
#pragma once

#include <cstddef>
#include <span>
#include <string>

namespace vkpt::internal {

struct MeshoptStream {
  std::string mode = "ATTRIBUTES";  // ATTRIBUTES, TRIANGLES or INDICES
  std::string filter = "NONE";      // NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL
  size_t count = 0;                 // elements decoded
  size_t byteStride = 0;            // bytes per element
};

// The first thing wrong with `s` ("byteStride 6 is not 2 or 4 for TRIANGLES"), or "".
std::string CheckMeshoptStream(const MeshoptStream& s);

// Decodes `encoded` into `out`, which holds exactly s.count × s.byteStride bytes; `s`
// must pass CheckMeshoptStream. Throws Error naming no file when the data is
// malformed.
void DecodeMeshoptStream(std::span<const unsigned char> encoded, const MeshoptStream& s, std::span<unsigned char> out);

}  // namespace vkpt::internal

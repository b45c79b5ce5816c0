// The KHR_draco_mesh_compression codec on one primitive's bitstream (Google's Draco,
// bitstream 2.2): a triangle mesh decoded by libdraco, then its faces and the attributes
// the glTF accessors name written as those accessors lay them out. The bitstream comes
// from the file: what it decodes to is checked against what the accessors declared
// before a byte of it is used.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace vkpt::internal {

// One accessor of the primitive: the Draco attribute it takes its values from, and its
// layout (tightly packed elements of `components` × `componentType`).
struct DracoAccessor {
  std::string attribute;  // the glTF attribute name, for messages ("NORMAL")
  uint32_t uniqueId = 0;  // the Draco attribute's unique id
  int components = 0;     // 1 … 4
  int componentType = 0;  // a glTF component type (5120 … 5126, not 5124)
  size_t count = 0;       // the accessor's count: the mesh's points
};

struct DracoPrimitive {
  std::vector<uint32_t> indices;                       // 3 per face
  std::vector<std::vector<unsigned char>> attributes;  // per DracoAccessor, packed
};

// Decodes `bitstream`, which must hold a triangle mesh of `indexCount` / 3 faces and the
// `accessors`' points. Throws Error naming no file when it is malformed or disagrees.
DracoPrimitive DecodeDraco(std::span<const unsigned char> bitstream, const std::vector<DracoAccessor>& accessors,
                           size_t indexCount);

}  // namespace vkpt::internal

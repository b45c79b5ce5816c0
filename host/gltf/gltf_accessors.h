// glTF accessors: typed views of buffer data (glTF 2.0 spec §3.6). Their layout is
// checked against the bufferViews they read before anything is decoded, because a
// count or a stride in the file may point anywhere.
#pragma once

#include <cstddef>
#include <vector>

#include "gltf/gltf_source.h"

namespace vkpt::internal {

int ComponentSize(int componentType);  // bytes; 0 for an invalid type
int ComponentCount(int type);          // SCALAR 1 … MAT4 16; 0 for an invalid type
size_t ElementSize(const tinygltf::Accessor& a);

// Component type, element type, count, byteOffset alignment, bufferView range and
// stride, and the sparse substitution's index and value regions of accessors[index].
void CheckAccessor(const GltfSource& src, int index);

// All components of a checked accessor, element by element, as doubles, with the sparse
// substitution applied; normalized integers map to [0, 1] or [-1, 1] as the spec says.
std::vector<double> ReadAccessor(const GltfSource& src, int index);

}  // namespace vkpt::internal

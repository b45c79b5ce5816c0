// The checks tinygltf does not make: it accepts out-of-range indices, bufferViews that
// run past their buffer, node cycles, unresolved references and more. Each check names
// the glTF object at fault; the loader runs them before it reads the data they guard.
#pragma once

#include <string>
#include <vector>

#include "gltf/gltf_source.h"

namespace vkpt::internal {

// Whether vkpt renders every property of extension `name`: a file that *requires* any
// other is refused, as the glTF spec demands of a loader that does not implement it, and
// -v lists any other it uses as ignored.
bool IsSupportedExtension(const std::string& name);
// asset.version 2.x and no required extension vkpt lacks.
void CheckAsset(const GltfSource& src);
// Each bufferView inside its buffer, with a legal byteStride.
void CheckBufferViews(const GltfSource& src);
// Texture, image, sampler and material texture references resolve.
void CheckTexturesAndMaterials(const GltfSource& src);
void CheckCameras(const GltfSource& src);
// Child indices in range, no cycles, no node with two parents (the node graph must be a
// forest), checked without recursion so that a loop cannot overflow the stack. Returns
// each node's parent, -1 for a root.
std::vector<int> CheckNodeGraph(const GltfSource& src);
// A primitive's mode, material and attribute references, POSITION's and NORMAL's types
// (FLOAT VEC3, or quantized with KHR_mesh_quantization) and equal attribute counts.
void CheckPrimitive(const GltfSource& src, const tinygltf::Primitive& prim, const std::string& name);

}  // namespace vkpt::internal

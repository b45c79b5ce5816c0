// KHR_materials_variants: a file's named sets of materials (a shoe in three colours), one
// of which --variant renders instead of the primitives' own materials.
#pragma once

#include <string>
#include <vector>

#include "gltf/gltf_source.h"

namespace vkpt::internal {

// The file's variant names, in order (the extension's top-level `variants`); empty
// without the extension. Throws Error naming the file if the list is malformed.
std::vector<std::string> ReadVariants(const GltfSource& src);

// The index of `wanted` among `variants`: its name, else a decimal index; -1 for "".
// Throws Error naming the file and listing its variants if there is no such one.
int ResolveVariant(const GltfSource& src, const std::vector<std::string>& variants, const std::string& wanted);

// The material primitive `prim` (named `what`) takes in variant `variant`: the mapping's
// material where one of its mappings lists the variant, else −1 (its own material). The
// mappings are checked whatever the variant: material and variant indices in range.
int VariantMaterial(const GltfSource& src, const tinygltf::Primitive& prim, int variant, size_t variantCount,
                    const std::string& what);

}  // namespace vkpt::internal

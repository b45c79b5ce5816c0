// The GPU's layout of the BVH (shader::WideBvhNode): the binary tree collapsed into nodes
// of four children whose boxes are quantised to 8 bits per plane (Ylitie et al. 2017,
// "Efficient Incoherent Ray Traversal on GPUs Through Compressed Wide BVHs"), each node
// linked to its parent for the stackless walk of shaders/traverse.glsl. Derived from the
// flattened tree; the leaves index the same leaf-ordered triangles.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "shared/layout.h"

namespace vkpt::internal {

constexpr int kGpuBvhWidth = 4;

// From the `nodeCount` flattened nodes starting at nodes[0], `copies`
// (1 or 8) copies of the wide tree, equal but for the order of each node's children:
// copy o holds them near first for rays of octant o (bit 0: x < 0, bit 1: y < 0, bit 2:
// z < 0), so that the walk enters them in slot order; a single copy takes octant 0's.
// Each copy has the same number of nodes, its root first; a tree that is one leaf
// becomes a root with that leaf as its only child.
std::vector<shader::WideBvhNode> BuildQuantizedLayout(std::span<const shader::BvhNode> nodes, uint32_t nodeCount,
                                                      uint32_t copies);

// Child k's box as the shader computes it: origin + cell · q per plane.
struct QuantizedBox {
  glm::vec3 lo, hi;
};
QuantizedBox ChildBox(const shader::WideBvhNode& node, int k);

}  // namespace vkpt::internal

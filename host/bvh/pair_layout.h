// The CPU tracer's layout of the BVH: one 64-byte record per inner node holding the boxes
// of *both* children, axis by axis, so that one ray tests the pair with 4-wide vector
// arithmetic (Wald et al. 2008 call this the "child-pair" form; Embree's BVH4 is the
// 4-wide relative). Derived from the flattened skip-link tree (first copy), which stays
// what the GPU reads; the builder knows nothing about either layout.
#pragma once

#include <cstdint>
#include <vector>

#include "shared/layout.h"

namespace vkpt {

struct alignas(64) BvhPairNode {
  // bounds[axis] = {lo of child 0, lo of child 1, hi of child 0, hi of child 1}.
  float bounds[3][4];
  // Per child: (pair index << 4) for an inner child, or its leaf code
  // (first triangle << 4) | count, count in 1..15, exactly as shader::BvhNode::leaf.
  uint32_t child[2];
  uint32_t pad[2];
};
static_assert(sizeof(BvhPairNode) == 64);

inline bool IsLeafCode(uint32_t code) { return (code & 15u) != 0u; }

struct BvhPairLayout {
  // Pair 0 holds the root's children. Empty when the root itself is a leaf (rootLeaf).
  std::vector<BvhPairNode> pairs;
  uint32_t rootLeaf = 0;  // the root's leaf code when the whole tree is one leaf, else 0
};

// From `nodeCount` flattened nodes starting at nodes[0] (one copy of the tree).
BvhPairLayout BuildPairLayout(const std::vector<shader::BvhNode>& nodes, uint32_t nodeCount);

}  // namespace vkpt

// The CPU tracer's layout of the BVH: one 64-byte record per inner node holding the boxes
// of *both* children, axis by axis, so that one ray tests the pair with 4-wide vector
// arithmetic (Wald et al. 2008 call this the "child-pair" form; Embree's BVH4 is the
// 4-wide relative), and each leaf's triangles in packets of four, coordinates lane by
// lane, tested together. Derived from the flattened skip-link tree (first copy) and the
// leaf-ordered triangles, which stay what the GPU reads; the builder knows neither layout.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "shared/layout.h"
#include "util/float4.h"

namespace vkpt {

struct alignas(64) BvhPairNode {
  // bounds[axis] = {lo of child 0, lo of child 1, hi of child 0, hi of child 1}.
  float bounds[3][4];
  // Per child: (pair index << 4) for an inner child, or its leaf code
  // (first packet << 4) | triangle count, count in 1..15, in ⌈count / 4⌉ packets.
  uint32_t child[2];
  uint32_t pad[2];
};
static_assert(sizeof(BvhPairNode) == 64);

// Up to four triangles of one leaf as v0, e1, e2 per axis (lane k: the k-th triangle).
// Unused lanes hold a zero-area triangle at the origin, which no ray hits (det = 0).
struct TrianglePacket {
  Float4 v0[3], e1[3], e2[3];
  uint32_t index[4];  // leaf-order triangle (RenderScene::triangles), kInvalidIndex if unused
};
static_assert(sizeof(TrianglePacket) == 160);

inline bool IsLeafCode(uint32_t code) { return (code & 15u) != 0u; }

struct BvhPairLayout {
  // Pair 0 holds the root's children. Empty when the root itself is a leaf (rootLeaf).
  std::vector<BvhPairNode> pairs;
  std::vector<TrianglePacket> packets;
  uint32_t rootLeaf = 0;  // the root's leaf code when the whole tree is one leaf, else 0
};

// From `nodeCount` flattened nodes starting at nodes[0] (one copy of the tree) and the
// triangles their leaves index.
BvhPairLayout BuildPairLayout(std::span<const shader::BvhNode> nodes, uint32_t nodeCount,
                              const std::vector<shader::Triangle>& triangles);

}  // namespace vkpt

// The CPU tracer's layout of the BVH: the binary tree collapsed into nodes of up to eight
// children (Embree's BVH8; Wald et al. 2008, "Getting Rid of Packets"), each node holding
// its children's boxes axis by axis so that one ray tests all eight with one 8-wide AVX
// step (or two 4-wide ones), and each leaf's triangles in packets of four, coordinates
// lane by lane, tested together. Derived from the flattened skip-link tree
// and the leaf-ordered triangles, which stay what the GPU reads; the builder knows
// neither layout.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "shared/layout.h"
#include "util/float4.h"
#include "util/huge_pages.h"

namespace vkpt::internal {

// Children per node. Eight rather than four: a tree of half as many levels, so half as
// many nodes' worth of waiting on memory per ray (docs/design-notes.md, "CPU: wide nodes").
constexpr int kBvhWidth = 8;

struct alignas(64) BvhWideNode {
  // Child k's box is (lo[0][k], lo[1][k], lo[2][k]) – (hi[0][k], hi[1][k], hi[2][k]). An
  // unused lane holds the empty box lo = +∞, hi = −∞, which no ray enters.
  float lo[3][kBvhWidth];
  float hi[3][kBvhWidth];
  // Per child: (node index << 4) for an inner child, or its leaf code (first packet << 4)
  // | triangle count, count in 1..15, in ⌈count / 4⌉ packets; 0 in an unused lane.
  uint32_t child[kBvhWidth];
};
static_assert(sizeof(BvhWideNode) == 256);

// Up to four triangles of one leaf as v0, e1, e2 per axis (lane k: the k-th triangle).
// Unused lanes hold a zero-area triangle at the origin, which no ray hits (det = 0).
struct TrianglePacket {
  Float4 v0[3], e1[3], e2[3];
  uint32_t index[4];  // leaf-order triangle (RenderScene::triangles), kInvalidIndex if unused
};
static_assert(sizeof(TrianglePacket) == 160);

inline bool IsLeafCode(uint32_t code) { return (code & 15u) != 0u; }

struct BvhWideLayout {
  // Node 0 is the root. Empty when the root itself is a leaf (rootLeaf).
  // On huge pages: rays visit these at random, and with 4 KiB pages a large scene's walk
  // waits on TLB misses (docs/design-notes.md, "CPU prefetch").
  HugeVector<BvhWideNode> nodes;
  HugeVector<TrianglePacket> packets;
  uint32_t rootLeaf = 0;  // the root's leaf code when the whole tree is one leaf, else 0
};

// From `nodeCount` flattened nodes starting at nodes[0] and the triangles their leaves
// index, each inner node collapsed as bvh/collapse.h does.
BvhWideLayout BuildWideLayout(std::span<const shader::BvhNode> nodes, uint32_t nodeCount,
                              const std::vector<shader::Triangle>& triangles);

}  // namespace vkpt::internal

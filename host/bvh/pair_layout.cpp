#include "bvh/pair_layout.h"

#include "bvh/bvh.h"
#include "util/error.h"

namespace vkpt {
namespace {

// Appends the packets of flattened leaf code `leaf`; returns the pair layout's leaf code.
uint32_t AddLeaf(uint32_t leaf, const std::vector<shader::Triangle>& triangles, std::vector<TrianglePacket>& packets) {
  const uint32_t first = leaf >> 4, count = leaf & 15u;
  const uint32_t code = uint32_t(packets.size()) << 4 | count;
  for (uint32_t k = 0; k < count; k += 4) {
    TrianglePacket p{};
    for (uint32_t lane = 0; lane < 4; ++lane) {
      p.index[lane] = shader::kInvalidIndex;
      if (k + lane >= count) continue;
      const shader::Triangle& t = triangles[first + k + lane];
      for (int axis = 0; axis < 3; ++axis) {
        p.v0[axis][lane] = t.v0[axis];
        p.e1[axis][lane] = t.e1[axis];
        p.e2[axis][lane] = t.e2[axis];
      }
      p.index[lane] = first + k + lane;
    }
    packets.push_back(p);
  }
  return code;
}

}  // namespace

BvhPairLayout BuildPairLayout(std::span<const shader::BvhNode> nodes, uint32_t nodeCount,
                              const std::vector<shader::Triangle>& triangles) {
  BvhPairLayout layout;
  if (nodeCount == 0 || nodes.size() < nodeCount) throw Error("BuildPairLayout: no tree to convert");
  if (IsLeaf(nodes[0])) {
    layout.rootLeaf = AddLeaf(nodes[0].leaf, triangles, layout.packets);
    return layout;
  }
  // Inner nodes get pair indices in depth-first order, so a parent precedes its children
  // (and near subtrees stay close in memory, as in the flattened tree); packets follow
  // the same order.
  std::vector<uint32_t> pairOf(nodeCount, 0);
  uint32_t inner = 0;
  size_t packets = 0;
  for (uint32_t i = 0; i < nodeCount; ++i) {
    if (!IsLeaf(nodes[i])) pairOf[i] = inner++;
    else packets += (LeafCount(nodes[i]) + 3) / 4;
  }
  if (inner > (1u << 28) || packets >= (1u << 28)) throw Error("BuildPairLayout: too many nodes for the 28-bit index");
  layout.pairs.resize(inner);
  layout.packets.reserve(packets);
  for (uint32_t i = 0; i < nodeCount; ++i) {
    if (IsLeaf(nodes[i])) continue;
    BvhPairNode& p = layout.pairs[pairOf[i]];
    const uint32_t kids[2] = {FirstChild(i), SecondChild(nodes, i)};
    for (int c = 0; c < 2; ++c) {
      const shader::BvhNode& k = nodes[kids[c]];
      for (int axis = 0; axis < 3; ++axis) {
        p.bounds[axis][c] = k.lo[axis];
        p.bounds[axis][2 + c] = k.hi[axis];
      }
      p.child[c] = IsLeaf(k) ? AddLeaf(k.leaf, triangles, layout.packets) : pairOf[kids[c]] << 4;
    }
  }
  return layout;
}

}  // namespace vkpt

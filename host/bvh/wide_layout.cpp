#include "bvh/wide_layout.h"

#include <limits>

#include "bvh/bvh.h"
#include "bvh/collapse.h"
#include "util/bounds.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

// Appends the packets of flattened leaf code `leaf`; returns the wide layout's leaf code.
uint32_t AddLeaf(uint32_t leaf, const std::vector<shader::Triangle>& triangles, HugeVector<TrianglePacket>& packets) {
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

BvhWideLayout BuildWideLayout(std::span<const shader::BvhNode> nodes, uint32_t nodeCount,
                              const std::vector<shader::Triangle>& triangles) {
  BvhWideLayout layout;
  if (nodeCount == 0 || nodes.size() < nodeCount) throw Error("BuildWideLayout: no tree to convert");
  if (IsLeaf(nodes[0])) {
    layout.rootLeaf = AddLeaf(nodes[0].leaf, triangles, layout.packets);
    return layout;
  }
  size_t packets = 0;
  for (uint32_t i = 0; i < nodeCount; ++i)
    if (IsLeaf(nodes[i])) packets += (LeafCount(nodes[i]) + 3) / 4;
  if (packets >= (1u << 28)) throw Error("BuildWideLayout: too many packets for the 28-bit index");
  layout.packets.reserve(packets);
  // Depth first, a node's first inner child right after it in memory (as the flattened
  // tree keeps near subtrees close); packets follow the same order. Each entry: a binary
  // inner node and the lane of the wide node that points to it.
  struct Pending {
    uint32_t binary, parent, lane;
  };
  std::vector<Pending> stack = {{0, 0, 0}};
  while (!stack.empty()) {
    const Pending e = stack.back();
    stack.pop_back();
    const uint32_t wide = uint32_t(layout.nodes.size());
    if (wide >= (1u << 28)) throw Error("BuildWideLayout: too many nodes for the 28-bit index");
    if (wide > 0) layout.nodes[e.parent].child[e.lane] = wide << 4;
    const CollapsedChildren<kBvhWidth> kids = CollapseChildren<kBvhWidth>(nodes, e.binary);
    BvhWideNode node{};
    for (int axis = 0; axis < 3; ++axis)
      for (int k = 0; k < kBvhWidth; ++k) {
        const bool used = k < kids.count;
        node.lo[axis][k] = used ? nodes[kids.node[k]].lo[axis] : std::numeric_limits<float>::infinity();
        node.hi[axis][k] = used ? nodes[kids.node[k]].hi[axis] : -std::numeric_limits<float>::infinity();
      }
    for (int k = 0; k < kids.count; ++k) {
      const shader::BvhNode& c = nodes[kids.node[k]];
      if (IsLeaf(c)) node.child[k] = AddLeaf(c.leaf, triangles, layout.packets);
    }
    layout.nodes.push_back(node);
    for (int k = kids.count - 1; k >= 0; --k)
      if (!IsLeaf(nodes[kids.node[k]])) stack.push_back({kids.node[k], wide, uint32_t(k)});
  }
  layout.nodes.shrink_to_fit();
  return layout;
}

}  // namespace vkpt::internal

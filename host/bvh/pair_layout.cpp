#include "bvh/pair_layout.h"

#include "bvh/bvh.h"
#include "util/error.h"

namespace vkpt {

BvhPairLayout BuildPairLayout(const std::vector<shader::BvhNode>& nodes, uint32_t nodeCount) {
  BvhPairLayout layout;
  if (nodeCount == 0 || nodes.size() < nodeCount) throw Error("BuildPairLayout: no tree to convert");
  if (IsLeaf(nodes[0])) {
    layout.rootLeaf = nodes[0].leaf;
    return layout;
  }
  // Inner nodes get pair indices in depth-first order, so a parent precedes its children
  // (and near subtrees stay close in memory, as in the flattened tree).
  std::vector<uint32_t> pairOf(nodeCount, 0);
  uint32_t inner = 0;
  for (uint32_t i = 0; i < nodeCount; ++i)
    if (!IsLeaf(nodes[i])) pairOf[i] = inner++;
  if (inner > (1u << 28)) throw Error("BuildPairLayout: too many nodes for the 28-bit index");
  layout.pairs.resize(inner);
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
      p.child[c] = IsLeaf(k) ? k.leaf : pairOf[kids[c]] << 4;
    }
  }
  return layout;
}

}  // namespace vkpt

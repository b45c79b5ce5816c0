// Collapsing the binary tree into wide nodes (Wald et al. 2008, "Getting Rid of Packets";
// Embree's BVH4/BVH8): the children a wide node takes in place of an inner binary node.
#pragma once

#include <cstdint>
#include <span>

#include "bvh/bvh.h"
#include "util/bounds.h"

namespace vkpt::internal {

// Up to Width binary nodes, in the binary tree's order.
template <int Width>
struct CollapsedChildren {
  uint32_t node[Width];
  int count = 0;
};

// Inner binary node i's two children, then, while there is room and one of them is inner,
// the inner child of the largest surface area replaced in place by its two children: the
// nodes a ray is likeliest to enter are the ones merged away.
template <int Width>
CollapsedChildren<Width> CollapseChildren(std::span<const shader::BvhNode> nodes, uint32_t i) {
  CollapsedChildren<Width> kids;
  kids.node[0] = FirstChild(i);
  kids.node[1] = SecondChild(nodes, i);
  kids.count = 2;
  while (kids.count < Width) {
    int widest = -1;
    float widestArea = 0.0f;
    for (int k = 0; k < kids.count; ++k) {
      const shader::BvhNode& c = nodes[kids.node[k]];
      const float area = Bounds3f{c.lo, c.hi}.SurfaceArea();
      if (!IsLeaf(c) && (widest < 0 || area > widestArea)) widest = k, widestArea = area;
    }
    if (widest < 0) break;
    const uint32_t n = kids.node[widest];
    for (int k = kids.count; k > widest + 1; --k) kids.node[k] = kids.node[k - 1];
    kids.node[widest] = FirstChild(n);
    kids.node[widest + 1] = SecondChild(nodes, n);
    ++kids.count;
  }
  return kids;
}

}  // namespace vkpt::internal

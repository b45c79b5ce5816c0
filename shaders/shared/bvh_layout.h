// The BVH's node layouts, shared by C++ and GLSL under layout.h's rules (std430, 4-byte
// scalars; host/render/gpu_layout.cpp static_asserts the sizes and offsets).
#ifndef VKPT_BVH_LAYOUT_H
#define VKPT_BVH_LAYOUT_H
#include "prelude.h"  // first, as in every shared header

VKPT_BEGIN_NAMESPACE

// A flattened BVH node (32 bytes) in depth-first order with skip links: the builder's
// output, from which the host derives the CPU's eight-wide nodes and the GPU's
// WideBvhNode; no shader reads it.
//   skip: index of the node to visit when this node's box is missed or its leaf is
//         done (kInvalidIndex: traversal ends). For an inner node the first child is
//         the next node (index + 1) and the second child is nodes[index + 1].skip.
//   leaf: 0 for an inner node; for a leaf (first << 4) | count with 1 <= count <= 15.
struct BvhNode {
  vec3 lo;
  uint skip;
  vec3 hi;
  uint leaf;
};

// The GPU's node (64 bytes, four texels): up to four children's boxes quantised to 8
// bits per plane against this node's grid (Ylitie et al. 2017, "Efficient Incoherent Ray
// Traversal on GPUs Through Compressed Wide BVHs"), child k in byte k of each word.
//   origin, exponents: the grid. Axis a's cell is 2^(byte a of exponents − 127); child
//         k's box is origin + cell · (lo bytes k) to origin + cell · (hi bytes k), which
//         contains its subtree's box exactly. Bits 24–25: this node's slot in its parent.
//   lo.w: the parent node (kInvalidIndex for the root); hi.w: 0.
//   child: (node index << 4) for an inner child, a leaf code as BvhNode::leaf, 0 for an
//         unused slot (used slots come first, near first for the copy's octant).
struct WideBvhNode {
  vec3 origin;
  uint exponents;
  uvec4 lo;
  uvec4 hi;
  uvec4 child;
};

const uint kMaxLeafSize = 15u;

VKPT_END_NAMESPACE

#endif

// The BVH as the builder leaves it (tree_builder.cpp), before it is laid out for the
// renderers (flatten.cpp): nodes in an array with unused gaps, each node's primitives a
// range of the primitive array. Internal to host/bvh/.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "bvh/bvh.h"
#include "util/bounds.h"
#include "util/float4.h"
#include "util/huge_pages.h"

namespace vkpt::internal {

// 32 bytes, laid out so that 16-byte loads at box.lo and box.hi give x, y, z in lanes 0-2
// (lane 3 holds the next field and is ignored). The centroid is not stored: it is
// (lo + hi) / 2, computed where needed exactly as Bounds3f::Center does; every pass over
// the primitives then moves a fifth less memory.
struct BuildPrim {
  Bounds3f box;
  uint32_t index;
  uint32_t pad;  // left uninitialised in bulk fills: nothing reads it

  float Centroid(int axis) const { return (box.lo[axis] + box.hi[axis]) * 0.5f; }
  Float4 Centroid4() const { return (Load4(&box.lo.x) + Load4(&box.hi.x)) * Splat4(0.5f); }
};
static_assert(sizeof(BuildPrim) == 32 && offsetof(Bounds3f, hi) == 12);

// 36 bytes. The node array is allocated once for the largest possible tree and
// filled in place, so its elements are left uninitialised until a parent writes them.
struct BuildNode {
  Bounds3f box;
  uint32_t first, count;  // the node's primitive range in the prims array
  uint32_t child;         // inner: the first child (the second follows it); leaf: 0
                          // (the root is nobody's child)
  bool IsLeaf() const { return child == 0; }
};
static_assert(sizeof(BuildNode) == 36);

struct BuildTree {
  HugeVector<BuildNode> nodes;  // the root at 0; only nodes reachable from it are valid
  HugeVector<BuildPrim> prims;  // leaves' ranges index this; BuildPrim::index is the input's
  float rootArea = 0.0f;        // the root box's surface area
};

// The binned SAH tree over primitive boxes `bounds` (tree_builder.cpp), built on
// `threads` threads (the tree is the same for any count). `vertices`, three per
// primitive, allow spatial splits; empty for object splits only.
BuildTree BuildTreeOver(std::span<const Bounds3f> bounds, const BvhBuildOptions& options,
                        std::span<const glm::vec3> vertices, unsigned threads);

// What the flat layout needs to know of a BuildTree's inner nodes, by node index: the
// subtree's size (which places the second child), and which child is nearer for rays
// going which way — bits 0-1: the axis along which the children's centres differ most;
// bit 2: set if the second child's centre is below the first's on it (rays whose
// direction is negative on that axis visit the child with the lower centre first).
struct FlatInfo {
  HugeVector<uint32_t> size;
  HugeVector<uint8_t> near;
};

// A BuildTree on its way to a Bvh (flatten.cpp), in two steps: the constructor walks the
// tree for its statistics (the SAH cost among them) and for FlatInfo; Write() lays it
// out as the flattened skip-link tree. A caller choosing between trees (SplitMode::
// kAuto) thus writes only the one it keeps. Both steps run on up to `threads` threads
// and give the same result for any count.
class TreeLayout {
 public:
  TreeLayout(BuildTree tree, const BvhBuildOptions& options, unsigned threads);
  const BvhStats& Stats() const { return stats_; }
  uint32_t Copies() const;  // the GPU's direction copies of this tree: 8 while they fit, else 1
  Bvh Write() const;

 private:
  BuildTree tree_;
  BvhBuildOptions opt_;
  unsigned threads_;
  FlatInfo info_;
  BvhStats stats_;
};

}  // namespace vkpt::internal

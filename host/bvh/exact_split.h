// Exact object splits for small nodes: every position in the references' centroid order
// along each axis is a candidate plane, costed by the SAH as binned splits are (sah.h).
// For a few references this is cheaper than binning and finds the best plane there is.
// Internal to host/bvh/.
#pragma once

#include <cstdint>
#include <span>

#include "bvh/build_tree.h"
#include "bvh/sah.h"

namespace vkpt::internal {

// Nodes of at most this many references are split exactly.
constexpr uint32_t kExactSplitMax = 8;

struct ExactSplit {
  Split split;  // split.bin: how many references go left
  // The references (offsets into the node's) in centroid order along split.axis, ties
  // by primitive index; set if split.axis >= 0.
  uint8_t order[kExactSplitMax] = {};
};

// The best split of a node with box `box` and references `refs` (at most
// kExactSplitMax); none (axis -1) for a flat node, which the caller splits at the median.
ExactSplit FindExactSplit(std::span<const BuildPrim> refs, const Bounds3f& box, const BvhBuildOptions& o);

// Puts `refs` in split.order, so that the first split.bin go left.
void ApplyExactSplit(std::span<BuildPrim> refs, const ExactSplit& split);

}  // namespace vkpt::internal

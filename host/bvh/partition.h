// Putting an object split into effect: a node's references are reordered in place so
// that those left of the plane come first. Internal to host/bvh/.
#pragma once

#include <cstdint>
#include <span>

#include "bvh/object_split.h"

namespace vkpt::internal {

// Ranges of at least this many references are partitioned in fixed blocks (on all the
// threads given); smaller ones in one pass. Which way a range goes decides the order of
// the references, so the tree's triangle order depends on this constant but never on
// the thread count.
constexpr uint32_t kBlockedPartitionMin = 1u << 15;

struct Partition {
  uint32_t leftCount = 0;  // the left side is refs[0, leftCount)
  Bounds3f leftCentroids, rightCentroids;  // each side's centroid bounds
};

// Moves the references of `refs` whose centroid bin (by `map`) along split.axis is
// below split.bin to the front, on up to `threads` threads; the sides' centroid bounds
// are gathered on the way.
Partition PartitionByBin(std::span<BuildPrim> refs, const BinMap& map, const Split& split, unsigned threads);

}  // namespace vkpt::internal

#include "bvh/partition.h"

#include <algorithm>
#include <vector>

#include "util/parallel.h"

namespace vkpt::internal {
namespace {

constexpr uint32_t kBlock = 1u << 14;

// Partitions one range by Hoare's two-pointer scheme and returns where its right side
// starts; the centroids of both sides are gathered into lc and rc on the way.
uint32_t PartitionRange(std::span<BuildPrim> r, const BinMap& map, int axis, int32_t bin, Bin& lc, Bin& rc) {
  uint32_t i = 0, j = uint32_t(r.size());
  while (true) {
    Float4 ci = Splat4(0.0f), cj = ci;
    while (i < j && map.Of(ci = r[i].Centroid4())[axis] < bin) lc.Extend(ci, ci), ++i;
    while (i < j && map.Of(cj = r[j - 1].Centroid4())[axis] >= bin) rc.Extend(cj, cj), --j;
    if (i == j) return i;
    // r[i] goes right and r[j - 1] left.
    std::swap(r[i], r[j - 1]);
    lc.Extend(cj, cj), rc.Extend(ci, ci);
    ++i, --j;
  }
}

// A run of references in position order.
struct Run {
  uint32_t first, count;
};

// The references on the wrong side of `mid` once every block is partitioned on its own
// (block k's right side starts at split[k]): right-side runs before mid and left-side
// runs after it, in position order. Both hold the same number of references.
void FindMisplaced(uint32_t size, const std::vector<uint32_t>& split, uint32_t mid, std::vector<Run>& wrongRight,
                   std::vector<Run>& wrongLeft) {
  for (uint32_t k = 0; k < split.size(); ++k) {
    const uint32_t bb = k * kBlock, be = std::min(size, bb + kBlock);
    const uint32_t rightEnd = std::min(be, mid), leftStart = std::max(bb, mid);
    if (split[k] < rightEnd) wrongRight.push_back({split[k], rightEnd - split[k]});
    if (split[k] > leftStart) wrongLeft.push_back({leftStart, split[k] - leftStart});
  }
}

// Swaps the i-th misplaced right reference with the i-th misplaced left one, for i in
// one slice of [0, misplaced) per thread.
void SwapMisplaced(std::span<BuildPrim> refs, const std::vector<Run>& wrongRight, const std::vector<Run>& wrongLeft,
                   unsigned threads) {
  uint64_t misplaced = 0;
  for (const Run& r : wrongRight) misplaced += r.count;
  // Finds run and offset of the i-th element of `runs`.
  auto locate = [](const std::vector<Run>& runs, uint64_t i, size_t& run, uint32_t& offset) {
    for (run = 0; i >= runs[run].count; ++run) i -= runs[run].count;
    offset = uint32_t(i);
  };
  const unsigned slices = misplaced < kBlockedPartitionMin ? 1u : threads;
  ParallelFor(slices, slices, [&](size_t t) {
    uint64_t i = misplaced * t / slices, end = misplaced * (t + 1) / slices;
    if (i == end) return;
    size_t rr, lr;
    uint32_t ro, lo;
    locate(wrongRight, i, rr, ro);
    locate(wrongLeft, i, lr, lo);
    for (; i < end; ++i) {
      std::swap(refs[wrongRight[rr].first + ro], refs[wrongLeft[lr].first + lo]);
      if (++ro == wrongRight[rr].count) ++rr, ro = 0;
      if (++lo == wrongLeft[lr].count) ++lr, lo = 0;
    }
  });
}

// A large range: fixed blocks, each partitioned on its own (on all threads); then the
// right-side references left of the final boundary trade places with the left-side
// references right of it, pairwise in position order. The blocks do not depend on the
// thread count, so neither does the resulting order.
Partition PartitionBlocks(std::span<BuildPrim> refs, const BinMap& map, int axis, int32_t bin, unsigned threads) {
  const uint32_t size = uint32_t(refs.size()), blocks = (size + kBlock - 1) / kBlock;
  std::vector<uint32_t> split(blocks);  // where each block's right side starts
  std::vector<Bin> lc(blocks), rc(blocks);
  ParallelFor(blocks, threads, [&](size_t k) {
    const uint32_t bb = uint32_t(k) * kBlock;
    split[k] = bb + PartitionRange(refs.subspan(bb, std::min(size, bb + kBlock) - bb), map, axis, bin, lc[k], rc[k]);
  });
  uint32_t mid = 0;
  Bin left, right;
  for (uint32_t k = 0; k < blocks; ++k) {
    mid += split[k] - k * kBlock;
    left.Extend(lc[k].lo, lc[k].hi), right.Extend(rc[k].lo, rc[k].hi);
  }
  std::vector<Run> wrongRight, wrongLeft;
  FindMisplaced(size, split, mid, wrongRight, wrongLeft);
  SwapMisplaced(refs, wrongRight, wrongLeft, threads);
  return {mid, left.Box(), right.Box()};
}

}  // namespace

Partition PartitionByBin(std::span<BuildPrim> refs, const BinMap& map, const Split& split, unsigned threads) {
  const int32_t bin = int32_t(split.bin);
  if (refs.size() >= kBlockedPartitionMin) return PartitionBlocks(refs, map, split.axis, bin, threads);
  Bin lc, rc;
  const uint32_t mid = PartitionRange(refs, map, split.axis, bin, lc, rc);
  return {mid, lc.Box(), rc.Box()};
}

}  // namespace vkpt::internal

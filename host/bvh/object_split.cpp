#include "bvh/object_split.h"

#include "util/parallel.h"

namespace vkpt::internal {
namespace {

// Counts `refs` into out's bins by centroid: bins [a·nb, (a+1)·nb) for axis a, all three
// axes in one pass.
void BinRange(std::span<const BuildPrim> refs, const BinMap& map, uint32_t nb, std::vector<Bin>& out) {
  out.assign(3 * nb, Bin{});
  for (const BuildPrim& p : refs) {
    const Int4 k = map.Of(p.Centroid4());
    const Float4 boxLo = Load4(&p.box.lo.x), boxHi = Load4(&p.box.hi.x);
    for (int a = 0; a < 3; ++a) {
      Bin& bin = out[a * nb + uint32_t(k[a])];
      bin.Extend(boxLo, boxHi);
      ++bin.count;
    }
  }
}

// All of `refs` binned (as BinRange) on `threads` threads, each into bins of its own,
// then merged: min/max and counts merge exactly, so the result does not depend on
// `threads`. The bins are the calling thread's, reused across calls (no allocation per
// node) and valid until its next call.
const std::vector<Bin>& BinAll(std::span<const BuildPrim> refs, const BinMap& map, uint32_t nb, unsigned threads) {
  static thread_local std::vector<Bin> bins;
  if (threads == 1) {
    BinRange(refs, map, nb, bins);
    return bins;
  }
  std::vector<std::vector<Bin>> partial(threads);
  ForChunks(0, uint32_t(refs.size()), threads,
            [&](uint32_t b, uint32_t e, unsigned t) { BinRange(refs.subspan(b, e - b), map, nb, partial[t]); });
  bins.assign(3 * nb, Bin{});
  for (const std::vector<Bin>& mine : partial)
    for (uint32_t k = 0; k < 3 * nb; ++k) bins[k].Merge(mine[k]);
  return bins;
}

}  // namespace

Split FindObjectSplit(std::span<const BuildPrim> refs, const Bounds3f& box, const Bounds3f& centroids,
                      const BvhBuildOptions& o, unsigned threads) {
  Split best;
  const float parentArea = box.SurfaceArea();
  const uint32_t nb = o.bins;
  const BinMap map(centroids, nb);
  const std::vector<Bin>& all = BinAll(refs, map, nb, threads);
  for (int a = 0; a < 3; ++a) {
    if (!map.Usable(a)) continue;
    const Bin* bins = all.data() + a * nb;
    auto count = [&](uint32_t b) { return bins[b].count; };
    SweepBins(bins, o, count, count, parentArea, [&](uint32_t b, float cost, const Bin& left, const Bin& right) {
      if (cost < best.cost) best = {a, b, cost, left.Box(), right.Box()};
    });
  }
  if (!(parentArea > 0.0f)) best.axis = -1, best.cost = std::numeric_limits<float>::infinity();
  return best;
}

}  // namespace vkpt::internal

#include "bvh/exact_split.h"

#include <algorithm>

namespace vkpt::internal {
namespace {

// sorted[a][k]: the reference of rank k along axis a. Each reference's rank along all
// three axes is found at once, by comparing every pair (centroids, ties by primitive
// index): no data-dependent branches, unlike a sort of so few items.
void RankCentroids(const BuildPrim* p, uint32_t n, uint8_t sorted[3][kExactSplitMax]) {
  Float4 c[kExactSplitMax];
  Int4 rank[kExactSplitMax];
  for (uint32_t i = 0; i < n; ++i) c[i] = p[i].Centroid4(), rank[i] = Int4{0, 0, 0, 0};
  for (uint32_t i = 0; i < n; ++i)
    for (uint32_t j = i + 1; j < n; ++j) {
      const Int4 tie = p[i].index < p[j].index ? Int4{-1, -1, -1, -1} : Int4{0, 0, 0, 0};
      const Int4 iFirst = (c[i] < c[j]) | ((c[i] == c[j]) & tie);  // lanes: -1 or 0
      rank[j] -= iFirst;
      rank[i] += iFirst + 1;
    }
  for (uint32_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) sorted[a][rank[i][a]] = uint8_t(i);
}

}  // namespace

ExactSplit FindExactSplit(std::span<const BuildPrim> refs, const Bounds3f& box, const BvhBuildOptions& o) {
  ExactSplit result;
  Split& best = result.split;
  const uint32_t n = uint32_t(refs.size());
  const float parentArea = box.SurfaceArea();
  if (!(parentArea > 0.0f)) return result;
  const BuildPrim* p = refs.data();
  uint8_t sorted[3][kExactSplitMax];
  RankCentroids(p, n, sorted);
  Bin right[kExactSplitMax];
  for (int a = 0; a < 3; ++a) {
    const uint8_t* s = sorted[a];
    Bin acc;
    for (uint32_t k = n - 1; k > 0; --k) {
      acc.Extend(Load4(&p[s[k]].box.lo.x), Load4(&p[s[k]].box.hi.x));
      right[k] = acc;
    }
    acc = Bin{};
    for (uint32_t k = 1; k < n; ++k) {
      acc.Extend(Load4(&p[s[k - 1]].box.lo.x), Load4(&p[s[k - 1]].box.hi.x));
      const float cost = SplitCost(o, acc.Area(), float(k), right[k].Area(), float(n - k), parentArea);
      if (cost < best.cost) best = {a, k, cost, acc.Box(), right[k].Box()};
    }
  }
  if (best.axis >= 0) std::copy(sorted[best.axis], sorted[best.axis] + n, result.order);
  return result;
}

void ApplyExactSplit(std::span<BuildPrim> refs, const ExactSplit& split) {
  BuildPrim sorted[kExactSplitMax];
  for (uint32_t k = 0; k < refs.size(); ++k) sorted[k] = refs[split.order[k]];
  std::copy(sorted, sorted + refs.size(), refs.begin());
}

}  // namespace vkpt::internal

// The surface area heuristic (Goldsmith and Salmon 1987, MacDonald and Booth 1990) as
// the builder's split finders share it: a box-and-count accumulator (Bin), the cost of
// a split, and the sweep that costs every plane between a row of bins (Wald 2007).
// Internal to host/bvh/.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "bvh/bvh.h"
#include "util/bounds.h"
#include "util/float4.h"

namespace vkpt::internal {

// A box in lanes 0-2 of lo and hi (lane 3 is whatever the primitives carried), and how
// many references it holds.
struct Bin {
  Float4 lo = Splat4(std::numeric_limits<float>::infinity());
  Float4 hi = Splat4(-std::numeric_limits<float>::infinity());
  uint32_t count = 0;

  void Extend(Float4 boxLo, Float4 boxHi) {
    lo = Min4(lo, boxLo);
    hi = Max4(hi, boxHi);
  }
  void Merge(const Bin& b) {
    Extend(b.lo, b.hi);
    count += b.count;
  }
  bool Empty() const { return !(lo[0] <= hi[0]); }
  Bounds3f Box() const { return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}; }
  // Bounds3f::SurfaceArea of Box(), for a bin that holds something.
  float Area() const {
    Float4 d = hi - lo;
    return 2.0f * (d[0] * d[1] + d[1] * d[2] + d[2] * d[0]);
  }
};

// An object split: the references ranked below `bin` along `axis` go left (a bin index
// for binned splits, a count for exact ones); axis -1 if no plane was found.
struct Split {
  int axis = -1;
  uint32_t bin = 0;
  float cost = std::numeric_limits<float>::infinity();
  Bounds3f left, right;  // the children's boxes
};

// The SAH cost of splitting a node of area parentArea into children of these areas and
// reference counts, in triangle tests.
inline float SplitCost(const BvhBuildOptions& o, float leftArea, float leftCount, float rightArea, float rightCount,
                       float parentArea) {
  return o.traversalCost + o.intersectionCost * (leftArea * leftCount + rightArea * rightCount) / parentArea;
}

// The SAH sweep over one axis's o.bins bins: the side right of every plane b (bins >= b)
// accumulated from the right, then the left sides from the left, each plane costed.
// A bin adds enters(b) references to the sides left of the planes above it and exits(b)
// to the sides right of the planes at or below it: both are its count for object bins;
// for spatial bins, the references that start and end there. consider(b, cost, left,
// right) sees every plane with references on both sides. (Small nodes make most of the
// calls, so this runs on vectors too.)
template <class Enters, class Exits, class Consider>
void SweepBins(const Bin* bins, const BvhBuildOptions& o, Enters&& enters, Exits&& exits, float parentArea,
               Consider&& consider) {
  static thread_local std::vector<Bin> right;
  const uint32_t nb = o.bins;
  right.resize(nb);
  Bin acc;
  for (uint32_t b = nb - 1; b > 0; --b) {
    acc.Extend(bins[b].lo, bins[b].hi);
    acc.count += exits(b);
    right[b] = acc;
  }
  acc = Bin{};
  for (uint32_t b = 1; b < nb; ++b) {
    acc.Extend(bins[b - 1].lo, bins[b - 1].hi);
    acc.count += enters(b - 1);
    if (acc.count == 0 || right[b].count == 0) continue;
    // Past an empty bin the plane splits as the one before it did, at the same cost.
    if (bins[b - 1].Empty() && enters(b - 1) == 0 && exits(b - 1) == 0) continue;
    consider(b, SplitCost(o, acc.Area(), float(acc.count), right[b].Area(), float(right[b].count), parentArea), acc,
             right[b]);
  }
}

}  // namespace vkpt::internal

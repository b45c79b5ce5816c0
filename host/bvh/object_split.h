// Object splits by binning (Wald 2007, "On fast Construction of SAH-based Bounding Volume
// Hierarchies"): a node's references are counted into bins by centroid along each axis,
// and the plane between two bins with the lowest SAH cost wins. Internal to host/bvh/.
#pragma once

#include <cstdint>
#include <span>

#include "bvh/build_tree.h"
#include "bvh/sah.h"

namespace vkpt::internal {

// Centroid → bin index along all three axes at once: nb bins spanning the node's
// centroid bounds. Binning and partitioning both use it, so they agree to the last bit.
// An axis with no centroid extent has scale 0: everything lands in bin 0 and the sweep
// skips the axis.
struct BinMap {
  Float4 lo, scale, last;
  BinMap(const Bounds3f& centroids, uint32_t nb) {
    float s[3];
    for (int a = 0; a < 3; ++a) {
      const float extent = centroids.hi[a] - centroids.lo[a];
      s[a] = extent > 0.0f ? float(nb) / extent : 0.0f;
    }
    lo = Float4{centroids.lo.x, centroids.lo.y, centroids.lo.z, 0.0f};
    scale = Float4{s[0], s[1], s[2], 0.0f};
    last = Splat4(float(nb - 1));
  }
  bool Usable(int axis) const { return scale[axis] > 0.0f; }
  // Clamped before the conversion: SSE2 has no integer min.
  Int4 Of(Float4 centroid) const {
    return __builtin_convertvector(Min4(Max4((centroid - lo) * scale, Splat4(0.0f)), last), Int4);
  }
};

// The cheapest of the o.bins - 1 planes per axis for a node with box `box`, references
// `refs` and their centroids' bounds `centroids`, binned on `threads` threads (the result
// is the same for any count). No plane (axis -1) for a flat node, whose costs are all NaN
// or ∞: the caller splits it at the median.
Split FindObjectSplit(std::span<const BuildPrim> refs, const Bounds3f& box, const Bounds3f& centroids,
                      const BvhBuildOptions& o, unsigned threads);

}  // namespace vkpt::internal

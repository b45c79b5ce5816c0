// Clipping a triangle to a slab between two planes, for spatial splits (Stich et al.
// 2009): the bounds of the part of a triangle on one side of a plane. Internal to
// host/bvh/.
#pragma once

#include <limits>

#include "util/bounds.h"
#include "util/float4.h"

namespace vkpt::internal {

// A box in lanes 0-2 of two vectors.
struct Box4 {
  Float4 lo, hi;
  bool Empty() const { return (Mask4(lo <= hi) & 7) != 7; }
};

// The box of the part of triangle v[0..2] (x, y, z in lanes 0-2) with lo <= p[axis] <=
// hi: the vertices inside the slab and the points where edges cross its planes (empty if
// nothing is inside). The crossings are rounded: a caller that needs a conservative box
// pads it (Conservative).
inline Box4 ClipTriangle(const Float4 v[3], int axis, float lo, float hi) {
  Float4 lo4 = Splat4(std::numeric_limits<float>::infinity());
  Float4 hi4 = Splat4(-std::numeric_limits<float>::infinity());
  // A crossing lies on its plane exactly: its `axis` lane is replaced by a mask (writing
  // one lane of a register through memory would stall on the reload).
  const Int4 onAxis = Int4{0, 1, 2, 3} == Int4{axis, axis, axis, axis};
  for (int i = 0; i < 3; ++i) {
    const Float4 p = v[i], q = v[(i + 1) % 3];
    const float pa = p[axis], qa = q[axis];
    if (pa >= lo && pa <= hi) lo4 = Min4(lo4, p), hi4 = Max4(hi4, p);
    for (float plane : {lo, hi}) {
      if ((pa < plane && qa > plane) || (pa > plane && qa < plane)) {
        const Float4 x = onAxis ? Splat4(plane) : p + (q - p) * Splat4((plane - pa) / (qa - pa));
        lo4 = Min4(lo4, x), hi4 = Max4(hi4, x);
      }
    }
  }
  return {lo4, hi4};
}

// A clipped part's box padded by a few ulps of its coordinates, so that rounding in the
// crossings cannot shave it, then cut to the reference's box (which stays conservative).
inline Bounds3f Conservative(const Box4& part, const Bounds3f& reference) {
  Bounds3f b{{part.lo[0], part.lo[1], part.lo[2]}, {part.hi[0], part.hi[1], part.hi[2]}};
  if (b.Empty()) return b;
  const glm::vec3 pad = (glm::abs(b.lo) + glm::abs(b.hi)) * 4e-7f + glm::vec3(1e-30f);
  b.lo -= pad;
  b.hi += pad;
  return Intersection(b, reference);
}

}  // namespace vkpt::internal

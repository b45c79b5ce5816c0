#include "quantized_layout_check.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "bvh/quantized_layout.h"
#include "util/bounds.h"

namespace vkpt::internal::test {

Bounds3f TriangleBounds(const shader::Triangle& t) {
  Bounds3f b;
  b.Extend(t.v0);
  b.Extend(t.v0 + t.e1);
  b.Extend(t.v0 + t.e2);
  return b;
}

namespace {

Bounds3f Box(const QuantizedBox& q) { return Bounds3f{q.lo, q.hi}; }

struct Walk {
  const RenderScene& rs;
  bool spatial;
  uint32_t base, count;
  std::vector<int> reached, inLeaves;

  // Checks node i and everything below it; returns the bounds of the triangles below it
  // (with spatial splits, empty: their clipped parts are not known here).
  Bounds3f Node(uint32_t i) {
    Bounds3f below;
    if (i < base || i >= base + count) {
      ADD_FAILURE() << "node " << i << " outside its copy";
      return below;
    }
    if (++reached[i - base] > 1) return below;  // reported by the caller
    const shader::WideBvhNode& n = rs.gpuNodes[i];
    for (int axis = 0; axis < 3; ++axis) {
      const uint32_t exponent = (n.exponents >> (8 * axis)) & 0xFFu;
      EXPECT_TRUE(exponent >= 1 && exponent <= 254) << "node " << i << ": a cell of 2^" << int(exponent) - 127;
    }
    int used = 0;
    for (int k = 0; k < kGpuBvhWidth; ++k) {
      const uint32_t code = n.child[k];
      if (code == 0u) continue;
      EXPECT_EQ(used++, k) << "node " << i << ": used slots come first";
      const Bounds3f box = Box(ChildBox(n, k));
      Bounds3f content;
      if ((code & 15u) != 0u) {
        const uint32_t first = code >> 4, end = first + (code & 15u);
        if (end > rs.triangles.size()) {
          ADD_FAILURE() << "node " << i << " slot " << k << ": triangles past the end";
          continue;
        }
        for (uint32_t t = first; t < end; ++t) {
          ++inLeaves[t];
          const Bounds3f tb = TriangleBounds(rs.triangles[t]);
          if (spatial) EXPECT_FALSE(Intersection(box, tb).Empty()) << "triangle " << t << " misses its leaf's box";
          else content.Extend(tb);
        }
      } else {
        const uint32_t child = code >> 4;
        EXPECT_GT(child, i) << "node " << i << " slot " << k << ": a child follows its parent";
        if (child < base || child >= base + count) {
          ADD_FAILURE() << "node " << i << " slot " << k << ": child " << child << " outside its copy";
          continue;
        }
        EXPECT_EQ(rs.gpuNodes[child].lo.w, i) << "node " << child << "'s parent link";
        EXPECT_EQ((rs.gpuNodes[child].exponents >> 24) & 3u, uint32_t(k)) << "node " << child << "'s slot";
        content = Node(child);
      }
      EXPECT_TRUE(box.Contains(content)) << "node " << i << " slot " << k << " does not contain what is below it";
      below.Extend(content);
    }
    EXPECT_GE(used, 1) << "node " << i;
    return below;
  }
};

}  // namespace

void CheckQuantizedLayout(const RenderScene& rs, bool spatial) {
  ASSERT_FALSE(rs.gpuNodes.empty());
  ASSERT_EQ(rs.gpuNodes.size() % rs.nodeCopies, 0u);
  const uint32_t count = uint32_t(rs.gpuNodes.size() / rs.nodeCopies);
  for (uint32_t copy = 0; copy < rs.nodeCopies; ++copy) {
    SCOPED_TRACE("copy " + std::to_string(copy));
    Walk walk{rs, spatial, copy * count, count, std::vector<int>(count, 0), std::vector<int>(rs.triangles.size(), 0)};
    EXPECT_EQ(rs.gpuNodes[walk.base].lo.w, shader::kInvalidIndex) << "the root has no parent";
    walk.Node(walk.base);
    for (uint32_t i = 0; i < count; ++i) ASSERT_EQ(walk.reached[i], 1) << "node " << walk.base + i;
    for (size_t t = 0; t < walk.inLeaves.size(); ++t) ASSERT_EQ(walk.inLeaves[t], 1) << "leaf-order triangle " << t;
  }
}

}  // namespace vkpt::internal::test

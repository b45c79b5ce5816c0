// The GPU's BVH layout (bvh/quantized_layout.h): quantised boxes that contain what is
// below them and are no more than a cell larger, copies ordered near first, and a check
// (quantized_layout_check.h, run on every tree test_bvh builds) that catches each kind of
// damage.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <string>

#include "bvh/quantized_layout.h"
#include "quantized_layout_check.h"
#include "render/render_scene.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

RenderScene Prepare(const std::vector<SceneTriangle>& tris, SplitMode splits = SplitMode::kObject) {
  Material m{};
  m.baseColor = glm::vec3(0.5f);
  BvhBuildOptions o;
  o.maxLeafSize = 4;
  o.splits = splits;
  return PrepareRenderScene(test::MakeScene(tris, {m}), o);
}

float Cell(const shader::WideBvhNode& n, int axis) {
  return std::bit_cast<float>(((n.exponents >> (8 * axis)) & 0xFFu) << 23);
}

// Each leaf slot's box against the triangles it holds: containing them, and within one
// cell of their bounds on every side (a layout that gave every child its whole node's
// box would pass the containment check and fail this one).
void ExpectLeafBoxesTight(const RenderScene& rs) {
  uint32_t leaves = 0;
  for (const shader::WideBvhNode& n : rs.gpuNodes)
    for (int k = 0; k < kGpuBvhWidth; ++k) {
      const uint32_t code = n.child[k];
      if (code == 0u || (code & 15u) == 0u) continue;
      ++leaves;
      Bounds3f tight;
      for (uint32_t t = code >> 4; t < (code >> 4) + (code & 15u); ++t)
        tight.Extend(test::TriangleBounds(rs.triangles[t]));
      const QuantizedBox box = ChildBox(n, k);
      for (int axis = 0; axis < 3; ++axis) {
        ASSERT_LE(box.lo[axis], tight.lo[axis]);
        ASSERT_GE(box.hi[axis], tight.hi[axis]);
        ASSERT_GE(box.lo[axis], tight.lo[axis] - Cell(n, axis)) << "axis " << axis;
        ASSERT_LE(box.hi[axis], tight.hi[axis] + Cell(n, axis)) << "axis " << axis;
      }
    }
  EXPECT_GT(leaves, 0u);
}

TEST(QuantizedLayout, LeafBoxesContainTheirTrianglesWithinACell) {
  ExpectLeafBoxesTight(Prepare(test::RandomSoup(4000, 5)));
}

// Scales far from the unit: a flat scene 1e-11 across (its cells along z the smallest,
// 2^-126) and one 1e16 across.
TEST(QuantizedLayout, ExtremeScalesKeepBoxesExact) {
  std::vector<SceneTriangle> tiny = test::RandomSoup(300, 8), huge = tiny;
  const glm::vec3 flat(1e-12f, 1e-12f, 0.0f);
  for (SceneTriangle& t : tiny) t.v0 *= flat, t.v1 *= flat, t.v2 *= flat;
  for (SceneTriangle& t : huge) t.v0 *= 1e15f, t.v1 *= 1e15f, t.v2 *= 1e15f;
  for (const auto& tris : {tiny, huge}) {
    const RenderScene rs = Prepare(tris);
    test::CheckQuantizedLayout(rs, false);
    ExpectLeafBoxesTight(rs);
  }
}

// A scene that is one leaf becomes a root with that leaf in its only slot.
TEST(QuantizedLayout, OneLeafTreeHasARootWithOneChild) {
  const RenderScene rs = Prepare(test::RandomSoup(3, 2));
  ASSERT_EQ(rs.gpuNodes.size(), rs.nodeCopies);
  EXPECT_EQ(rs.gpuNodes[0].child[0], 0u << 4 | 3u);
  EXPECT_EQ(rs.gpuNodes[0].child[1], 0u);
  test::CheckQuantizedLayout(rs, false);
}

// In copy o, a node's children come near first for directions of octant o: by their
// centres projected on the octant's diagonal, to within the cells that quantising moves
// each of the six planes.
TEST(QuantizedLayout, CopiesAreNearFirstForTheirOctant) {
  const RenderScene rs = Prepare(test::RandomSoup(3000, 17));
  ASSERT_EQ(rs.nodeCopies, 8u);
  const size_t count = rs.gpuNodes.size() / 8;
  uint32_t pairs = 0;
  for (uint32_t o = 0; o < 8; ++o) {
    const glm::vec3 diagonal((o & 1u) ? -1.0f : 1.0f, (o & 2u) ? -1.0f : 1.0f, (o & 4u) ? -1.0f : 1.0f);
    for (size_t i = o * count; i < (o + 1) * count; ++i) {
      const shader::WideBvhNode& n = rs.gpuNodes[i];
      const float slack = 2.0f * (Cell(n, 0) + Cell(n, 1) + Cell(n, 2));
      for (int k = 0; k + 1 < kGpuBvhWidth && n.child[k + 1] != 0u; ++k) {
        const QuantizedBox a = ChildBox(n, k), b = ChildBox(n, k + 1);
        EXPECT_LE(glm::dot(a.lo + a.hi, diagonal), glm::dot(b.lo + b.hi, diagonal) + slack)
            << "copy " << o << " node " << i;
        ++pairs;
      }
    }
  }
  EXPECT_GT(pairs, 1000u);
}

// What CheckQuantizedLayout reports about `rs`: its failure messages, joined.
std::string Failures(const RenderScene& rs, bool spatial = false) {
  ::testing::TestPartResultArray results;
  {
    ::testing::ScopedFakeTestPartResultReporter reporter(
        ::testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &results);
    test::CheckQuantizedLayout(rs, spatial);
  }
  std::string all;
  for (int i = 0; i < results.size(); ++i) all += results.GetTestPartResult(i).message();
  return all;
}

// CheckQuantizedLayout has teeth: each kind of broken layout fails it, for its reason.
TEST(QuantizedLayout, CheckFindsEachKindOfDamage) {
  const RenderScene good = Prepare(test::RandomSoup(500, 3));
  EXPECT_EQ(Failures(good), "");
  EXPECT_EQ(Failures(Prepare(test::RandomSoup(500, 3), SplitMode::kSpatial), true), "");
  ASSERT_GT(good.gpuNodes.size() / good.nodeCopies, 4u);
  auto damaged = [&](auto&& damage) {
    RenderScene rs = good;
    damage(rs.gpuNodes);
    return Failures(rs);
  };
  const shader::WideBvhNode& root = good.gpuNodes[0];
  int inner = 0;
  while ((root.child[inner] & 15u) != 0u) ++inner;
  const uint32_t child = root.child[inner] >> 4;
  using Nodes = std::vector<shader::WideBvhNode>;
  // A slot's box that leaves out part of its subtree: its upper x plane at its lower one.
  EXPECT_NE(damaged([&](Nodes& n) {
              n[0].hi.x = (n[0].hi.x & ~(0xFFu << (8 * inner))) | (n[0].lo.x & (0xFFu << (8 * inner)));
            }).find("does not contain what is below it"),
            std::string::npos);
  // A leaf's triangles outside its box: every leaf slot shrunk to its lower corner.
  EXPECT_NE(damaged([&](Nodes& n) {
              for (shader::WideBvhNode& node : n)
                for (int k = 0; k < kGpuBvhWidth; ++k)
                  if ((node.child[k] & 15u) != 0u)
                    node.hi.y = (node.hi.y & ~(0xFFu << (8 * k))) | (node.lo.y & (0xFFu << (8 * k)));
            }).find("does not contain what is below it"),
            std::string::npos);
  // A wrong parent link, a wrong slot.
  EXPECT_NE(damaged([&](Nodes& n) { n[child].lo.w = child; }).find("parent link"), std::string::npos);
  EXPECT_NE(damaged([&](Nodes& n) { n[child].exponents ^= 1u << 24; }).find("slot"), std::string::npos);
  // A triangle listed twice, another never: a leaf one triangle longer.
  EXPECT_NE(damaged([&](Nodes& n) {
              for (shader::WideBvhNode& node : n)
                for (int k = 0; k < kGpuBvhWidth; ++k)
                  if ((node.child[k] & 15u) != 0u && (node.child[k] & 15u) < 15u && (node.child[k] >> 4) == 0u) {
                    node.child[k] += 1u;
                    return;
                  }
            }).find("leaf-order triangle"),
            std::string::npos);
  // An unused slot between used ones.
  EXPECT_NE(damaged([&](Nodes& n) {
              for (shader::WideBvhNode& node : n)
                if (node.child[2] != 0u && (node.child[1] & 15u) != 0u) {
                  node.child[1] = 0u;
                  return;
                }
            }).find("used slots come first"),
            std::string::npos);
  // An exponent outside the normal floats.
  EXPECT_NE(damaged([&](Nodes& n) { n[0].exponents |= 0xFFu; }).find("a cell of"), std::string::npos);
}

}  // namespace
}  // namespace vkpt::internal

// BVH invariants and closest-hit traversal against brute force.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>

#include "bvh/bvh.h"
#include "cpu/traversal.h"
#include "gltf/gltf_loader.h"
#include "procedural.h"
#include "quantized_layout_check.h"
#include "render/render_scene.h"
#include "shared/estimator.h"
#include "shared/intersect.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

RenderScene Prepare(const std::vector<SceneTriangle>& tris, uint32_t leafSize = 4, bool spatialSplits = false) {
  Material m{};
  m.baseColor = glm::vec3(0.5f);
  BvhBuildOptions o;
  o.maxLeafSize = leafSize;
  o.splits = spatialSplits ? SplitMode::kSpatial : SplitMode::kObject;
  return PrepareRenderScene(test::MakeScene(tris, {m}), o);
}

// Long thin triangles at random orientations through a unit cube: their boxes overlap
// badly, what spatial splits are for.
std::vector<SceneTriangle> Slivers(uint32_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<SceneTriangle> tris;
  for (uint32_t i = 0; i < count; ++i) {
    glm::vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    glm::vec3 side = 0.01f * glm::vec3(u(rng), u(rng), u(rng));
    tris.push_back({a, b, a + side, 0});
  }
  return tris;
}

// BuildBvh's input for triangles: their boxes, and their vertices for spatial splits.
std::pair<std::vector<Bounds3f>, std::vector<glm::vec3>> BuildInput(const std::vector<SceneTriangle>& tris) {
  std::pair<std::vector<Bounds3f>, std::vector<glm::vec3>> in;
  for (const SceneTriangle& t : tris) {
    Bounds3f b;
    for (glm::vec3 v : {t.v0, t.v1, t.v2}) b.Extend(v);
    in.first.push_back(b);
    in.second.insert(in.second.end(), {t.v0, t.v1, t.v2});
  }
  return in;
}

// Checks every structural invariant of the flattened layout; returns the subtree end.
// With spatial splits a leaf holds only part of a triangle, so its box need only meet
// the triangle's.
uint32_t CheckSubtree(const RenderScene& rs, uint32_t i, uint32_t skip, uint32_t maxLeaf, std::vector<int>& seen,
                      uint32_t& leafTriangles, bool spatial) {
  const shader::BvhNode& n = rs.nodes[i];
  EXPECT_EQ(n.skip, skip) << "node " << i;
  Bounds3f box{n.lo, n.hi};
  if (IsLeaf(n)) {
    EXPECT_GE(LeafCount(n), 1u);
    EXPECT_LE(LeafCount(n), maxLeaf);
    for (uint32_t k = LeafFirst(n); k < LeafFirst(n) + LeafCount(n); ++k) {
      Bounds3f t = test::TriangleBounds(rs.triangles[k]);
      if (spatial)
        EXPECT_FALSE((Bounds3f{glm::max(box.lo, t.lo), glm::min(box.hi, t.hi)}.Empty())) << "leaf " << i << " triangle " << k;
      else
        EXPECT_TRUE(box.Contains(t)) << "leaf " << i << " triangle " << k;
      ++seen[rs.triangles[k].sourceIndex];
    }
    leafTriangles += LeafCount(n);
    return i + 1;
  }
  uint32_t a = FirstChild(i);
  uint32_t b = SecondChild(rs.nodes, i);
  EXPECT_TRUE(box.Contains(Bounds3f{rs.nodes[a].lo, rs.nodes[a].hi})) << "node " << i;
  EXPECT_TRUE(box.Contains(Bounds3f{rs.nodes[b].lo, rs.nodes[b].hi})) << "node " << i;
  uint32_t endA = CheckSubtree(rs, a, b, maxLeaf, seen, leafTriangles, spatial);
  EXPECT_EQ(endA, b);
  return CheckSubtree(rs, b, skip, maxLeaf, seen, leafTriangles, spatial);
}

// A leaf of the wide layout (CheckWideLayout): its packets copy its triangles exactly,
// each counted in `inPackets`, inside `box` (spatial splits: meeting it; no box: the root
// leaf), lanes past the count unused.
void CheckWideLeaf(const RenderScene& rs, uint32_t code, const Bounds3f& box, bool spatial,
                   std::vector<int>& inPackets) {
  const BvhWideLayout& w = rs.wideLayout;
  const uint32_t count = code & 15u;
  ASSERT_LE((code >> 4) + (count + 3) / 4, w.packets.size());
  for (uint32_t k = 0; k < (count + 3) / 4 * 4; ++k) {
    const TrianglePacket& p = w.packets[(code >> 4) + k / 4];
    const uint32_t lane = k % 4, i = p.index[lane];
    if (k >= count) {
      EXPECT_EQ(i, shader::kInvalidIndex);
      continue;
    }
    ASSERT_LT(i, rs.triangles.size());
    ++inPackets[i];
    const shader::Triangle& t = rs.triangles[i];
    for (int axis = 0; axis < 3; ++axis)
      EXPECT_TRUE(p.v0[axis][lane] == t.v0[axis] && p.e1[axis][lane] == t.e1[axis] && p.e2[axis][lane] == t.e2[axis]);
    const Bounds3f tb = test::TriangleBounds(t);
    if (box.Empty()) continue;  // the root leaf: no box
    if (spatial) EXPECT_FALSE((Bounds3f{glm::max(box.lo, tb.lo), glm::min(box.hi, tb.hi)}.Empty()));
    else EXPECT_TRUE(box.Contains(tb));
  }
}

// The CPU's wide layout of copy 0 (bvh/wide_layout.h): every node reached once, after its
// parent; each used lane's box contains its child's boxes or its leaf's triangles (with
// spatial splits: meets them), packets copy their triangles exactly, and every leaf-order
// triangle sits in exactly one packet lane; unused lanes hold the empty box, and a node
// has fewer than kBvhWidth children only when all of them are leaves (the collapse goes on
// while one is inner).
void CheckWideLayout(const RenderScene& rs, bool spatial) {
  const BvhWideLayout& w = rs.wideLayout;
  std::vector<int> inPackets(rs.triangles.size(), 0);
  if (w.nodes.empty()) {
    ASSERT_TRUE(IsLeafCode(w.rootLeaf));
    CheckWideLeaf(rs, w.rootLeaf, Bounds3f{}, spatial, inPackets);
  } else {
    EXPECT_EQ(w.rootLeaf, 0u);
    std::vector<int> reached(w.nodes.size(), 0);
    std::vector<std::pair<uint32_t, Bounds3f>> stack = {{0u, Bounds3f{rs.nodes[0].lo, rs.nodes[0].hi}}};
    while (!stack.empty()) {
      const auto [index, parentBox] = stack.back();
      stack.pop_back();
      ASSERT_LT(index, w.nodes.size());
      ++reached[index];
      const BvhWideNode& n = w.nodes[index];
      int used = 0, inner = 0;
      for (int k = 0; k < kBvhWidth; ++k) {
        const Bounds3f box{{n.lo[0][k], n.lo[1][k], n.lo[2][k]}, {n.hi[0][k], n.hi[1][k], n.hi[2][k]}};
        if (n.child[k] == 0u) {
          EXPECT_EQ(box.lo, glm::vec3(INFINITY)) << "node " << index << " lane " << k;
          EXPECT_EQ(box.hi, glm::vec3(-INFINITY)) << "node " << index << " lane " << k;
          continue;
        }
        EXPECT_EQ(used++, k) << "node " << index << ": used lanes come first";
        EXPECT_TRUE(parentBox.Contains(box)) << "node " << index << " lane " << k;
        if (IsLeafCode(n.child[k])) {
          CheckWideLeaf(rs, n.child[k], box, spatial, inPackets);
        } else {
          ++inner;
          EXPECT_GT(n.child[k] >> 4, index) << "a child follows its parent";
          stack.push_back({n.child[k] >> 4, box});
        }
      }
      EXPECT_GE(used, 2) << "node " << index;
      if (used < kBvhWidth) {
        EXPECT_EQ(inner, 0) << "node " << index << " has room for an inner child's children";
      }
    }
    for (size_t i = 0; i < reached.size(); ++i) ASSERT_EQ(reached[i], 1) << "wide node " << i;
  }
  for (size_t i = 0; i < inPackets.size(); ++i) ASSERT_EQ(inPackets[i], 1) << "leaf-order triangle " << i;
}

// The flattened tree must be complete and valid, and so must the layouts made from it.
// Each triangle appears once (spatial splits: at least once) unless degenerate.
void CheckInvariants(const RenderScene& rs, const std::vector<SceneTriangle>& input, uint32_t maxLeaf,
                     bool spatial = false) {
  const uint32_t triangleCount = uint32_t(input.size());
  ASSERT_EQ(rs.nodes.size(), size_t(rs.bvhStats.nodes));
  EXPECT_EQ(rs.triangles.size(), rs.bvhStats.references);
  if (!spatial) {
    EXPECT_EQ(rs.triangles.size() + rs.degenerateTriangles, triangleCount);
  }
  std::vector<int> seen(triangleCount, 0);
  uint32_t leafTriangles = 0;
  uint32_t end = CheckSubtree(rs, 0, shader::kInvalidIndex, maxLeaf, seen, leafTriangles, spatial);
  EXPECT_EQ(end, rs.bvhStats.nodes) << "every node is reachable from the root";
  EXPECT_EQ(leafTriangles, rs.triangles.size());
  for (uint32_t i = 0; i < triangleCount; ++i) {
    if (IsDegenerate(input[i])) ASSERT_EQ(seen[i], 0) << "degenerate triangle " << i;
    else if (spatial) ASSERT_GE(seen[i], 1) << "triangle " << i;
    else ASSERT_EQ(seen[i], 1) << "triangle " << i;
  }
  CheckWideLayout(rs, spatial);
  test::CheckQuantizedLayout(rs, spatial);
}

// What CheckWideLayout reports about `rs`: its failure messages, joined.
std::string WideLayoutFailures(const RenderScene& rs) {
  ::testing::TestPartResultArray results;
  {
    ::testing::ScopedFakeTestPartResultReporter reporter(
        ::testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &results);
    CheckWideLayout(rs, false);
  }
  std::string all;
  for (int i = 0; i < results.size(); ++i) all += results.GetTestPartResult(i).message();
  return all;
}

// CheckWideLayout has teeth: each kind of broken wide layout fails it, for its reason.
TEST(Bvh, WideLayoutCheckFindsEachKindOfDamage) {
  const RenderScene good = Prepare(test::RandomSoup(500, 3), 4);
  EXPECT_EQ(WideLayoutFailures(good), "");
  ASSERT_GT(good.wideLayout.nodes.size(), 4u);
  auto damaged = [&](auto&& damage) {
    RenderScene rs = good;
    damage(rs.wideLayout);
    return WideLayoutFailures(rs);
  };
  const BvhWideNode& root = good.wideLayout.nodes[0];
  const int inner = IsLeafCode(root.child[0]) ? 1 : 0;  // a root lane with an inner child
  ASSERT_FALSE(IsLeafCode(root.child[inner]));
  // A child's box outside its lane's.
  EXPECT_NE(damaged([&](BvhWideLayout& w) { w.nodes[0].hi[1][inner] -= 0.1f; }).find("parentBox.Contains"),
            std::string::npos);
  // A packet that is not its triangle.
  EXPECT_NE(damaged([&](BvhWideLayout& w) { w.packets[3].v0[2][0] += 1e-3f; }).find("p.v0"), std::string::npos);
  // A triangle listed twice, another never.
  EXPECT_NE(
      damaged([&](BvhWideLayout& w) { w.packets[0].index[0] = w.packets[0].index[1]; }).find("leaf-order triangle"),
      std::string::npos);
  // An unused lane that a ray could enter.
  EXPECT_NE(damaged([&](BvhWideLayout& w) {
              for (BvhWideNode& n : w.nodes)
                if (n.child[kBvhWidth - 1] == 0u) n.hi[0][kBvhWidth - 1] = 0.0f;
            }).find("box.hi"),
            std::string::npos);
  // An unused lane between used ones.
  auto clearLane = [](BvhWideNode& n, int k) {
    n.child[k] = 0u;
    for (int axis = 0; axis < 3; ++axis) n.lo[axis][k] = INFINITY, n.hi[axis][k] = -INFINITY;
  };
  EXPECT_NE(damaged([&](BvhWideLayout& w) {
              for (BvhWideNode& n : w.nodes)
                if (n.child[2] != 0u) clearLane(n, 1);
            }).find("used lanes come first"),
            std::string::npos);
  // A node with room left while a child is inner (the root's last lane dropped).
  EXPECT_NE(damaged([&](BvhWideLayout& w) { clearLane(w.nodes[0], kBvhWidth - 1); }).find("has room"),
            std::string::npos);
}

// An inner node's first child is the nearer one for rays of positive directions, along
// the axis that separates the children's centres most.
TEST(Bvh, FlattenedTreeIsNearFirst) {
  RenderScene rs = Prepare(test::RandomSoup(3000, 17), 4);
  uint32_t checked = 0;
  for (uint32_t i = 0; i < rs.bvhStats.nodes; ++i) {
    if (IsLeaf(rs.nodes[i])) continue;
    const shader::BvhNode& a = rs.nodes[FirstChild(i)];
    const shader::BvhNode& b = rs.nodes[SecondChild(rs.nodes, i)];
    glm::vec3 d = (b.lo + b.hi) * 0.5f - (a.lo + a.hi) * 0.5f;
    glm::vec3 ad = glm::abs(d);
    int axis = ad.x >= ad.y && ad.x >= ad.z ? 0 : (ad.y >= ad.z ? 1 : 2);
    // The second child lies further along +axis.
    if (d[axis] != 0.0f) {
      ASSERT_GT(d[axis], 0.0f) << "node " << i;
    }
    ++checked;
  }
  EXPECT_GT(checked, 100u);
}

TEST(Bvh, InvariantsOnRandomSoups) {
  for (uint32_t leaf : {1u, 4u, 15u}) {
    for (uint32_t count : {1u, 2u, 5u, 100u, 5000u}) {
      SCOPED_TRACE("leaf " + std::to_string(leaf) + ", " + std::to_string(count) + " triangles");
      std::vector<SceneTriangle> soup = test::RandomSoup(count, count * 7 + leaf);
      RenderScene rs = Prepare(soup, leaf);
      CheckInvariants(rs, soup, leaf);
      EXPECT_LE(rs.bvhStats.maxLeafPrims, leaf);
    }
  }
  // Large enough that the top nodes are partitioned block-wise on several threads.
  std::vector<SceneTriangle> soup = test::RandomSoup(100000, 99);
  CheckInvariants(Prepare(soup, 4), soup, 4);
}

TEST(Bvh, SameTreeForAnyBuildThreadCount) {
  // 100k triangles: the top levels are binned on several threads and the rest is built
  // as independent subtrees; the flattened result must not depend on the thread count.
  std::vector<SceneTriangle> soup = test::RandomSoup(100000, 23);
  std::vector<Bounds3f> bounds;
  for (const SceneTriangle& t : soup) {
    Bounds3f b;
    b.Extend(t.v0);
    b.Extend(t.v1);
    b.Extend(t.v2);
    bounds.push_back(b);
  }
  BvhBuildOptions o;
  o.threads = 1;
  Bvh one = BuildBvh(bounds, o);
  for (unsigned threads : {2u, 3u, 8u}) {
    o.threads = threads;
    Bvh many = BuildBvh(bounds, o);
    std::printf("%u threads: %.1f ms (1 thread: %.1f ms), %u nodes\n", threads, many.stats.buildMs, one.stats.buildMs,
                many.stats.nodes);
    ASSERT_EQ(many.nodes.size(), one.nodes.size());
    EXPECT_EQ(0, std::memcmp(many.nodes.data(), one.nodes.data(), one.nodes.size() * sizeof(shader::BvhNode)));
    EXPECT_EQ(many.primOrder, one.primOrder);
    EXPECT_EQ(many.stats.sahCost, one.stats.sahCost);
  }
}

TEST(Bvh, SmallNodesSplitAtTheBestPositionInCentroidOrder) {
  // Nodes of up to 8 primitives are split exactly: every position in the centroid order
  // along every axis is costed. Brute force the same over the root and compare children.
  auto area = [](const Bounds3f& b) {
    const glm::vec3 d = b.hi - b.lo;
    return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
  };
  for (uint32_t n = 2; n <= 8; ++n) {
    for (uint32_t seed = 0; seed < 40; ++seed) {
      SCOPED_TRACE(std::to_string(n) + " primitives, seed " + std::to_string(seed));
      std::vector<Bounds3f> bounds;
      for (const SceneTriangle& t : test::RandomSoup(n, 1000 * n + seed)) {
        Bounds3f b;
        for (glm::vec3 p : {t.v0, t.v1, t.v2}) b.Extend(p);
        bounds.push_back(b);
      }
      Bounds3f root;
      for (const Bounds3f& b : bounds) root.Extend(b);
      float bestCost = std::numeric_limits<float>::infinity();
      Bounds3f bestLeft, bestRight;
      for (int a = 0; a < 3; ++a) {
        std::vector<Bounds3f> sorted = bounds;
        std::sort(sorted.begin(), sorted.end(),
                  [a](const Bounds3f& p, const Bounds3f& q) { return p.lo[a] + p.hi[a] < q.lo[a] + q.hi[a]; });
        for (uint32_t k = 1; k < n; ++k) {
          Bounds3f left, right;
          for (uint32_t i = 0; i < n; ++i) (i < k ? left : right).Extend(sorted[i]);
          const float cost = 1.0f + (area(left) * float(k) + area(right) * float(n - k)) / area(root);
          if (cost < bestCost) bestCost = cost, bestLeft = left, bestRight = right;
        }
      }
      BvhBuildOptions o;
      o.maxLeafSize = 1;  // every node with two or more primitives must split
      Bvh bvh = BuildBvh(bounds, o);
      const shader::BvhNode &c0 = bvh.nodes[FirstChild(0)], &c1 = bvh.nodes[SecondChild(bvh.nodes, 0)];
      // Copy 0 orders children near-first for +x+y+z rays: either may be the left one.
      const bool leftFirst = c0.lo == bestLeft.lo && c0.hi == bestLeft.hi;
      const shader::BvhNode& l = leftFirst ? c0 : c1;
      const shader::BvhNode& r = leftFirst ? c1 : c0;
      EXPECT_EQ(l.lo, bestLeft.lo);
      EXPECT_EQ(l.hi, bestLeft.hi);
      EXPECT_EQ(r.lo, bestRight.lo);
      EXPECT_EQ(r.hi, bestRight.hi);
    }
  }
}

TEST(Bvh, SameSpatialSplitTreeForAnyBuildThreadCount) {
  // Spatial splits share the duplication budget out by subtree, so the tree does not
  // depend on which thread builds what either.
  std::vector<SceneTriangle> slivers = Slivers(60000, 31);
  const auto [bounds, vertices] = BuildInput(slivers);
  BvhBuildOptions o;
  o.splits = SplitMode::kSpatial;
  o.threads = 1;
  Bvh one = BuildBvh(bounds, o, vertices);
  EXPECT_GT(one.stats.references, bounds.size());
  for (unsigned threads : {2u, 3u}) {
    o.threads = threads;
    Bvh many = BuildBvh(bounds, o, vertices);
    std::printf("spatial splits, %u threads: %.1f ms (1 thread: %.1f ms), %u references\n", threads, many.stats.buildMs,
                one.stats.buildMs, many.stats.references);
    ASSERT_EQ(many.nodes.size(), one.nodes.size());
    EXPECT_EQ(0, std::memcmp(many.nodes.data(), one.nodes.data(), one.nodes.size() * sizeof(shader::BvhNode)));
    EXPECT_EQ(many.primOrder, one.primOrder);
    EXPECT_EQ(many.stats.sahCost, one.stats.sahCost);
  }
}

TEST(Bvh, IdenticalTrianglesStillRespectLeafSize) {
  // 1000 copies of one triangle: no SAH plane separates them, the median split must.
  std::vector<SceneTriangle> tris(1000, SceneTriangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0});
  RenderScene rs = Prepare(tris, 4);
  CheckInvariants(rs, tris, 4);
  std::printf("1000 identical triangles: %u nodes, depth %u\n", rs.bvhStats.nodes, rs.bvhStats.depth);
}

TEST(Bvh, SahBeatsMedianOnClusteredInput) {
  // Two far-apart clusters of very different sizes: the SAH cost must be close to the
  // cost of the two clusters traversed separately, far below a single leaf's.
  std::vector<SceneTriangle> tris = test::RandomSoup(4000, 3);
  RenderScene rs = Prepare(tris, 4);
  std::printf("SAH cost %.3f for 4000 random triangles (%u nodes, depth %u)\n", rs.bvhStats.sahCost,
              rs.bvhStats.nodes, rs.bvhStats.depth);
  EXPECT_LT(rs.bvhStats.sahCost, 4000.0 / 10.0);
  EXPECT_GT(rs.bvhStats.sahCost, 1.0);
}

struct BruteHit {
  float t = -1.0f;
  uint32_t tri = shader::kInvalidIndex;
};

BruteHit BruteForce(const RenderScene& rs, glm::vec3 o, glm::vec3 d) {
  BruteHit best;
  float tMax = shader::kInfinity;
  for (uint32_t i = 0; i < rs.triangles.size(); ++i) {
    const shader::Triangle& t = rs.triangles[i];
    glm::vec3 r = shader::IntersectTriangle(t.v0, t.e1, t.e2, o, d, tMax);
    if (r.x >= 0.0f) {
      best = {r.x, i};
      tMax = r.x;
    }
  }
  return best;
}

// Traversal must find exactly the brute-force closest hit; a different triangle is
// accepted only on a true tie (the same t). Every walk this CPU can run (portable, AVX2)
// returns the same bits for every query.
void CompareWithBruteForce(const RenderScene& rs, uint32_t rays, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Bounds3f b{rs.nodes[0].lo, rs.nodes[0].hi};
  glm::vec3 ext = b.Diagonal();
  uint32_t hits = 0, ties = 0, mismatches = 0, occlusionMismatches = 0, walksDiffer = 0;
  for (uint32_t i = 0; i < rays; ++i) {
    glm::vec3 o = b.lo - 0.25f * ext + 1.5f * ext * glm::vec3(u(rng), u(rng), u(rng));
    glm::vec3 d;
    if (i % 2) {
      // Aim at a random point of a random triangle, so most rays hit something.
      const shader::Triangle& t = rs.triangles[std::min<size_t>(size_t(u(rng) * rs.triangles.size()), rs.triangles.size() - 1)];
      glm::vec3 target = t.v0 + u(rng) * 0.5f * t.e1 + u(rng) * 0.5f * t.e2;
      d = target - o;
    } else {
      d = glm::vec3(u(rng), u(rng), u(rng)) * 2.0f - 1.0f;
    }
    if (i % 17 == 0) d.x = 0.0f;  // axis-parallel directions exercise the slab test
    if (i % 19 == 0) d.y = d.z = 0.0f;
    if (glm::length(d) == 0.0f) continue;
    d = glm::normalize(d);
    BruteHit ref = BruteForce(rs, o, d);
    Hit h = IntersectClosest(rs, o, d, shader::kInfinity);
    if (ref.t >= 0.0f) ++hits;
    if (h.t != ref.t) {
      ++mismatches;
      if (mismatches <= 5)
        ADD_FAILURE() << "ray " << i << ": traversal t=" << h.t << " tri " << h.triangle << ", brute force t=" << ref.t
                      << " tri " << ref.tri;
    } else if (h.triangle != ref.tri) {
      ++ties;
    }
    // Any-hit must agree with the closest hit about whether something is in the way.
    float tMax = ref.t >= 0.0f ? ref.t * 1.5f : 100.0f;
    bool expectOccluded = ref.t >= 0.0f;
    const bool occluded = Occluded(rs, o, d, tMax);
    if (occluded != expectOccluded) ++occlusionMismatches;
    for (WalkIsa isa : {WalkIsa::kPortable, WalkIsa::kAvx2}) {
      if (!WalkIsaSupported(isa)) continue;
      const Hit w = IntersectClosest(isa, rs, o, d, shader::kInfinity);
      walksDiffer += std::memcmp(&w, &h, sizeof h) != 0 || Occluded(isa, rs, o, d, tMax) != occluded;
    }
  }
  std::printf(
      "%u rays: %u hits, %u ties, %u mismatches, %u occlusion mismatches; %u differ between the portable "
      "and AVX2 walks%s\n",
      rays, hits, ties, mismatches, occlusionMismatches, walksDiffer,
      WalkIsaSupported(WalkIsa::kAvx2) ? "" : " (this CPU has no AVX2: the portable walk alone)");
  EXPECT_EQ(mismatches, 0u);
  EXPECT_EQ(occlusionMismatches, 0u);
  EXPECT_EQ(walksDiffer, 0u);
  EXPECT_GT(hits, rays / 4) << "the test must exercise hits, not only misses";
}

TEST(Bvh, TraversalMatchesBruteForceOnRandomSoups) {
  // 2 soups × 60k rays = 120k rays.
  CompareWithBruteForce(Prepare(test::RandomSoup(600, 11), 4), 60000, 1);
  CompareWithBruteForce(Prepare(test::RandomSoup(300, 12), 15), 60000, 2);
}

// Spatial splits must lower the SAH cost where boxes overlap, keep every triangle, and
// leave closest hits exactly as brute force finds them (clipped boxes stay conservative).
TEST(Bvh, SpatialSplitsCutOverlapAndKeepHitsExact) {
  std::vector<SceneTriangle> slivers = Slivers(2000, 9);
  RenderScene plain = Prepare(slivers, 4, false);
  RenderScene split = Prepare(slivers, 4, true);
  std::printf("slivers: SAH %.1f -> %.1f with spatial splits, %u -> %u references\n", plain.bvhStats.sahCost,
              split.bvhStats.sahCost, plain.bvhStats.references, split.bvhStats.references);
  EXPECT_LT(split.bvhStats.sahCost, 0.95 * plain.bvhStats.sahCost);  // measured: 9 % lower
  EXPECT_GT(split.bvhStats.references, plain.bvhStats.references);
  EXPECT_LE(split.bvhStats.references, 2 * plain.bvhStats.references) << "the duplication budget";
  CheckInvariants(split, slivers, 4, true);
  CompareWithBruteForce(split, 30000, 4);
  std::vector<SceneTriangle> soup = test::RandomSoup(600, 13);
  RenderScene soupSplit = Prepare(soup, 4, true);
  CheckInvariants(soupSplit, soup, 4, true);
  CompareWithBruteForce(soupSplit, 30000, 5);
}

// A triangle in several leaves is still one light: the emitter table must not change.
TEST(Bvh, SpatialSplitsKeepWholeTrianglesOnceTheDuplicationBudgetIsSpent) {
  // A budget of 20 duplicates runs out early: every later straddling triangle must go
  // whole (with its full box) to one side, or the part on the other side is lost.
  std::vector<SceneTriangle> slivers = Slivers(2000, 17);
  Material m{};
  m.baseColor = glm::vec3(0.5f);
  BvhBuildOptions o;
  o.splits = SplitMode::kSpatial;
  o.maxDuplication = 0.01f;
  RenderScene rs = PrepareRenderScene(test::MakeScene(slivers, {m}), o);
  EXPECT_LE(rs.bvhStats.references, 2020u);
  CheckInvariants(rs, slivers, o.maxLeafSize, true);
  CompareWithBruteForce(rs, 30000, 6);
}

TEST(Bvh, SpatialSplitsListEachLightOnce) {
  Material light{};
  light.emission = glm::vec3(2.0f);
  Scene scene = test::MakeScene(Slivers(500, 3), {light});
  BvhBuildOptions o;
  RenderScene plain = PrepareRenderScene(scene, o);
  o.splits = SplitMode::kSpatial;
  RenderScene split = PrepareRenderScene(scene, o);
  ASSERT_GT(split.triangles.size(), plain.triangles.size()) << "the test needs duplicated triangles";
  EXPECT_EQ(split.lights.size(), plain.lights.size());
  EXPECT_NEAR(split.totalEmittedPower, plain.totalEmittedPower, 1e-9 * plain.totalEmittedPower);
  double pmf = 0.0;
  for (const shader::Light& l : split.lights) pmf += l.pmf;
  EXPECT_NEAR(pmf, 1.0, 1e-6);
}

// Small triangles in a closed room of ten large wall triangles: the SAH's greedy split at
// the root cuts the walls when spatial splits are allowed, and the whole tree costs more
// than with object splits, which set the walls apart.
std::vector<SceneTriangle> WalledRoom(uint32_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-0.8f, 0.8f);
  std::vector<SceneTriangle> tris;
  for (uint32_t i = 0; i < count; ++i) {
    glm::vec3 c(u(rng), u(rng), u(rng));
    tris.push_back({c, c + 0.01f * glm::vec3(u(rng), u(rng), u(rng)), c + 0.01f * glm::vec3(u(rng), u(rng), u(rng)), 0});
  }
  // Floor, ceiling and three walls of the cube [-1, 1]³, two triangles each.
  const glm::vec3 p[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  const int quads[5][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 2, 6, 7}, {0, 3, 7, 4}};
  for (const auto& q : quads) {
    tris.push_back({p[q[0]], p[q[1]], p[q[2]], 0});
    tris.push_back({p[q[0]], p[q[2]], p[q[3]], 0});
  }
  return tris;
}

// SplitMode::kAuto builds the tree of each mode and keeps the one with the lower SAH
// cost, byte for byte as that mode alone builds it; a tie keeps the object tree.
TEST(Bvh, AutoSplitsKeepTheTreeWithTheLowerSahCost) {
  struct Case {
    const char* name;
    std::vector<SceneTriangle> tris;
    SplitMode expected;
  };
  std::vector<SceneTriangle> quad = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, 0}, {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}, 0}};
  for (const Case& c : {Case{"slivers", Slivers(5000, 8), SplitMode::kSpatial},
                        Case{"walled room", WalledRoom(20000, 9), SplitMode::kObject},
                        Case{"one quad (a tie)", quad, SplitMode::kObject}}) {
    SCOPED_TRACE(c.name);
    const auto [bounds, vertices] = BuildInput(c.tris);
    BvhBuildOptions o;
    o.splits = SplitMode::kObject;
    const Bvh object = BuildBvh(bounds, o, vertices);
    o.splits = SplitMode::kSpatial;
    const Bvh spatial = BuildBvh(bounds, o, vertices);
    o.splits = SplitMode::kAuto;
    const Bvh automatic = BuildBvh(bounds, o, vertices);
    std::printf("%s: SAH cost %.3f with object splits, %.3f with spatial splits\n", c.name, object.stats.sahCost,
                spatial.stats.sahCost);
    EXPECT_FALSE(object.stats.spatialSplits);
    EXPECT_TRUE(spatial.stats.spatialSplits);
    const bool spatialWins = c.expected == SplitMode::kSpatial;
    if (spatialWins) EXPECT_LT(spatial.stats.sahCost, object.stats.sahCost);
    else EXPECT_GE(spatial.stats.sahCost, object.stats.sahCost);
    const Bvh& kept = spatialWins ? spatial : object;
    const Bvh& rejected = spatialWins ? object : spatial;
    EXPECT_EQ(automatic.stats.spatialSplits, spatialWins);
    EXPECT_EQ(automatic.stats.sahCost, kept.stats.sahCost);
    EXPECT_EQ(automatic.stats.rejectedSahCost, rejected.stats.sahCost);
    EXPECT_EQ(kept.stats.rejectedSahCost, 0.0);
    ASSERT_EQ(automatic.nodes.size(), kept.nodes.size());
    EXPECT_EQ(0, std::memcmp(automatic.nodes.data(), kept.nodes.data(), kept.nodes.size() * sizeof(shader::BvhNode)));
    EXPECT_EQ(automatic.primOrder, kept.primOrder);
    // Without vertices there is nothing to clip: every mode builds object splits.
    const Bvh noVertices = BuildBvh(bounds, o, {});
    EXPECT_FALSE(noVertices.stats.spatialSplits);
    EXPECT_EQ(noVertices.stats.sahCost, object.stats.sahCost);
    EXPECT_EQ(noVertices.stats.rejectedSahCost, 0.0);
  }
}

// Where the spatial tree's eight direction-ordered copies (for the GPU) do not fit
// maxCopiesBytes but the object tree's do, auto keeps the object tree although its SAH
// is higher.
TEST(Bvh, AutoSplitsKeepTheDirectionCopies) {
  const auto [bounds, vertices] = BuildInput(Slivers(5000, 8));
  BvhBuildOptions o;
  o.splits = SplitMode::kObject;
  const Bvh object = BuildBvh(bounds, o, vertices);
  o.splits = SplitMode::kSpatial;
  const Bvh spatial = BuildBvh(bounds, o, vertices);
  ASSERT_EQ(object.copies, 8u);
  ASSERT_GT(spatial.stats.nodes, object.stats.nodes);
  ASSERT_LT(spatial.stats.sahCost, object.stats.sahCost);
  o.maxCopiesBytes = uint64_t(8) * object.stats.nodes * sizeof(shader::BvhNode);  // just the object tree's
  o.splits = SplitMode::kAuto;
  const Bvh automatic = BuildBvh(bounds, o, vertices);
  EXPECT_EQ(automatic.copies, 8u);
  EXPECT_FALSE(automatic.stats.spatialSplits);
  EXPECT_EQ(automatic.stats.sahCost, object.stats.sahCost);
  EXPECT_EQ(automatic.stats.rejectedSahCost, spatial.stats.sahCost);
  // Without direction copies for either (the CPU's trees), the SAH decides again.
  o.directionCopies = false;
  EXPECT_TRUE(BuildBvh(bounds, o, vertices).stats.spatialSplits);
}

// The bench's 10 M-triangle scene (vkpt-bench --procedural 10000000): the object-split
// tree (the one `--splits auto` keeps for it) holds every invariant, and traversal finds
// the brute-force closest hit of sampled rays (10 M triangle tests per ray). The plain
// build runs it; under AddressSanitizer (76 s) it would repeat what the smaller trees'
// tests check there, at a twentieth of CI's time budget.
TEST(Bvh, TenMillionTrianglesKeepInvariantsAndMatchBruteForce) {
#if defined(VKPT_ADDRESS_SANITIZER)
  GTEST_SKIP() << "76 s under AddressSanitizer; the plain build runs it";
#endif
  const Scene scene = bench::ProceduralScene(10'000'000);
  BvhBuildOptions o;
  o.splits = SplitMode::kObject;
  const RenderScene rs = PrepareRenderScene(scene, o);
  ASSERT_GT(rs.triangles.size(), 9'900'000u);
  CheckInvariants(rs, scene.triangles, o.maxLeafSize);
  CompareWithBruteForce(rs, 48, 7);
}

TEST(Bvh, TraversalMatchesBruteForceOnCorpusModel) {
  VKPT_REQUIRE_SHARED_DATA();
  Scene scene = LoadGltf(test::CorpusPath("valid/Duck/glTF-Binary/Duck.glb"));
  RenderScene rs = PrepareRenderScene(scene);
  CheckInvariants(rs, scene.triangles, BvhBuildOptions{}.maxLeafSize);
  CompareWithBruteForce(rs, 8000, 3);
}

}  // namespace
}  // namespace vkpt::internal

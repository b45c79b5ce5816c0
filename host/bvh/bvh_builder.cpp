// Binned SAH builder (Wald 2007, "On fast Construction of SAH-based Bounding Volume
// Hierarchies"): primitives are binned by centroid along each axis, the split plane with
// the lowest surface-area-heuristic cost wins, and a node becomes a leaf when splitting
// would not pay; nodes of a few primitives are split exactly (every position in centroid
// order). Optionally, planes that cut triangles compete too (spatial splits). The tree is
// built into a BuildTree (build_tree.h), where every node's place follows from the tree
// itself, by workers that hand each other subtrees, and then laid out by flatten.cpp.
// The tree is the same for any thread count; the builder is iterative, so a pathological
// input cannot overflow the call stack.
#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <limits>
#include <mutex>
#include <thread>

#include "bvh/build_tree.h"
#include "util/error.h"
#include "util/parallel.h"

namespace vkpt {
namespace {

// Orders primitives by centroid along `axis`, ties by index (so the order is unique).
struct CentroidLess {
  int axis;
  bool operator()(const BuildPrim& p, const BuildPrim& q) const {
    const float cp = p.Centroid(axis), cq = q.Centroid(axis);
    return cp < cq || (cp == cq && p.index < q.index);
  }
};

// A bin's box in lanes 0-2 of lo and hi; lane 3 is whatever the primitives carried.
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

// Nodes with at least this many primitives may be binned on several threads; splitting
// one of at least kShareNode primitives may hand a child to another thread.
constexpr uint32_t kParallelNode = 1u << 15, kShareNode = 1u << 12;

// A small node is split exactly: every position in its centroid order is costed.
constexpr uint32_t kExactSplitMax = 8;

// A node to split, with its centroids' bounds (binning needs them). Its references sit
// in prims_[first, first + count) and may grow, by spatial splits, into the `slack` free
// slots after them; its descendants go to nodes [range, range + 2·(count + slack) − 2),
// the most a subtree over that many references can have: its children first, then the
// left child's range, then the right child's. So every node's place follows from the
// tree alone, whichever thread builds it.
struct Task {
  uint32_t node, range, slack;
  Bounds3f centroids;
};

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

struct Split {
  int axis = -1;
  uint32_t bin = 0;  // primitives with bin index < `bin` go left
  float cost = std::numeric_limits<float>::infinity();
  Bounds3f left, right;  // the children's boxes
};

// A spatial split: the plane at the lower boundary of spatial bin `bin` along `axis`.
struct SpatialSplit {
  int axis = -1;
  uint32_t bin = 0;
  float cost = std::numeric_limits<float>::infinity();
  Bin left, right;  // the children's boxes and reference counts, every straddler split
};

Bounds3f Intersection(const Bounds3f& a, const Bounds3f& b) {
  Bounds3f r;
  r.lo = glm::max(a.lo, b.lo);
  r.hi = glm::min(a.hi, b.hi);
  return r;
}

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
Bounds3f Conservative(const Box4& part, const Bounds3f& reference) {
  Bounds3f b{{part.lo[0], part.lo[1], part.lo[2]}, {part.hi[0], part.hi[1], part.hi[2]}};
  if (b.Empty()) return b;
  const glm::vec3 pad = (glm::abs(b.lo) + glm::abs(b.hi)) * 4e-7f + glm::vec3(1e-30f);
  b.lo -= pad;
  b.hi += pad;
  return Intersection(b, reference);
}

class Builder {
 public:
  // `vertices`: three per primitive for spatial splits; empty for object splits only.
  Builder(std::span<const Bounds3f> bounds, const BvhBuildOptions& o, std::span<const glm::vec3> vertices)
      : opt_(o), verts_(vertices), spatial_(vertices.size() == 3 * bounds.size()) {
    // The references spatial splits may add; the total stays below 2^28, what a leaf
    // code can address.
    const uint32_t n = uint32_t(bounds.size());
    duplicationBudget_ =
        spatial_ ? uint32_t(std::min<uint64_t>(uint64_t(double(o.maxDuplication) * double(n)), (1u << 28) - 1 - n)) : 0;
    // Below kShareNode primitives no subtree is ever handed over: one thread, and no
    // time spent starting others.
    threads_ = n < kShareNode ? 1u : o.threads ? o.threads : std::max(1u, std::thread::hardware_concurrency());
    // The primitives, with the root's box and centroid bounds, on all threads; the
    // budget's slots after them stay untouched until used.
    prims_.resize(n + duplicationBudget_);
    std::vector<Bounds3f> boxes(threads_), cents(threads_);
    ForChunks(0, n, threads_, [&](uint32_t b, uint32_t e, unsigned t) {
      for (uint32_t i = b; i < e; ++i) prims_[i].box = bounds[i], prims_[i].index = i;
      Scan(b, e, boxes[t], cents[t]);
    });
    // A tree over m references has at most 2m - 1 nodes.
    nodes_.resize(2 * (n + duplicationBudget_) - 1);
    BuildNode& root = nodes_[0];
    root = {{}, 0, n, 0};
    rootCentroids_ = Bounds3f{};
    for (unsigned t = 0; t < threads_; ++t) {
      root.box.Extend(boxes[t]);
      rootCentroids_.Extend(cents[t]);
    }
    rootArea_ = root.box.SurfaceArea();
  }

  TreeLayout Build() {
    const unsigned threads = threads_;
    // Workers take subtrees from a shared list and build them depth first on their own.
    // Splitting a node of at least kShareNode primitives while a thread is idle hands
    // its right child to that thread; a node of at least kParallelNode primitives met
    // while every other thread is idle (the root) is binned and partitioned on all
    // threads. The tree does not depend on any of this (see Task).
    std::mutex mutex;
    std::condition_variable wake;
    std::vector<Task> shared{{0, 1, duplicationBudget_, rootCentroids_}};
    unsigned busy = 0;  // workers holding a subtree
    FirstException error;  // after one, every worker stops
    auto work = [&] {
      std::vector<Task> local;
      for (;;) {
        {
          std::unique_lock lock(mutex);
          wake.wait(lock, [&] { return !shared.empty() || busy == 0 || error.Failed(); });
          if (shared.empty() || error.Failed()) return;
          local.push_back(shared.back());
          shared.pop_back();
          ++busy;
        }
        while (!local.empty() && !error.Failed()) {
          const Task task = local.back();
          local.pop_back();
          const uint32_t count = nodes_[task.node].count;
          unsigned inner = 1;
          if (threads > 1 && count >= kParallelNode) {
            std::lock_guard lock(mutex);
            if (shared.empty() && busy == 1) inner = threads;
          }
          const size_t before = local.size();
          Subdivide(task, local, inner);
          if (threads > 1 && count >= kShareNode && local.size() == before + 2) {
            std::lock_guard lock(mutex);
            if (threads - busy > shared.size()) {
              shared.push_back(local[before]);  // the right child
              local.erase(local.begin() + before);
              wake.notify_one();
            }
          }
        }
        std::lock_guard lock(mutex);
        if (--busy == 0 && shared.empty()) wake.notify_all();
      }
    };
    auto worker = [&] {
      error.Run(work);
      if (error.Failed()) {
        std::lock_guard lock(mutex);
        wake.notify_all();
      }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    error.Rethrow();
    if (spatial_) CompactReferences();
    return TreeLayout({std::move(nodes_), std::move(prims_), rootArea_}, opt_, threads_);
  }

 private:
  // The SAH sweep over one axis's bins: the side right of every plane b (bins >= b)
  // accumulated from the right, then the left sides from the left, each plane costed.
  // A bin adds enters(b) references to the sides left of the planes above it and exits(b)
  // to the sides right of the planes at or below it: both are its count for object bins;
  // for spatial bins, the references that start and end there. consider(b, cost, left,
  // right) sees every plane with references on both sides. (Small nodes make most of the
  // calls, so this runs on vectors too.)
  template <class Enters, class Exits, class Consider>
  void SweepBins(const Bin* bins, Enters&& enters, Exits&& exits, float parentArea, Consider&& consider) const {
    static thread_local std::vector<Bin> right;
    const uint32_t nb = opt_.bins;
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
      float cost = opt_.traversalCost +
                   opt_.intersectionCost * (acc.Area() * float(acc.count) + right[b].Area() * float(right[b].count)) /
                       parentArea;
      consider(b, cost, acc, right[b]);
    }
  }

  // The box of primitives [b, e) and their centroids' bounds, extended into box and cent.
  void Scan(uint32_t b, uint32_t e, Bounds3f& box, Bounds3f& cent) const {
    Bin boxBin, centBin;  // lane by lane min/max
    for (uint32_t i = b; i < e; ++i) {
      const BuildPrim& p = prims_[i];
      const Float4 c = p.Centroid4();
      boxBin.Extend(Load4(&p.box.lo.x), Load4(&p.box.hi.x));
      centBin.Extend(c, c);
    }
    if (b < e) box.Extend(boxBin.Box()), cent.Extend(centBin.Box());
  }

  // Splits the node of `task` (or leaves it a leaf): its children go to the start of
  // its range, and onto `work`, right then left. The node's box, primitive range and
  // child (0) are set; large nodes are binned on `threads` threads.
  void Subdivide(const Task& task, std::vector<Task>& work, unsigned threads) {
    const uint32_t ni = task.node;
    const BuildNode node = nodes_[ni];
    if (node.count < kParallelNode) threads = 1;
    if (node.count == 1) return;
    // The children's references are at node.first, left then right (leftCount +
    // rightCount <= count + slack). Children take their boxes from the split (the union
    // of their references' boxes, whichever way it was found) and their centroid bounds
    // from the pass that puts their references in place; small children need none.
    // `slack` free slots, shared in proportion to the counts, follow the references:
    // the right ones move up to leave the left child its share.
    auto addChildren = [&](uint32_t leftCount, const Bounds3f& leftBox, const Bounds3f& leftCent, uint32_t rightCount,
                           const Bounds3f& rightBox, const Bounds3f& rightCent, uint32_t slack) {
      const uint32_t leftSlack = uint32_t(uint64_t(slack) * leftCount / (leftCount + rightCount));
      const uint32_t rightFirst = node.first + leftCount + leftSlack;
      if (leftSlack > 0)
        std::copy_backward(prims_.begin() + node.first + leftCount, prims_.begin() + node.first + leftCount + rightCount,
                           prims_.begin() + rightFirst + rightCount);
      const uint32_t left = task.range;
      nodes_[left] = {leftBox, node.first, leftCount, 0};
      nodes_[left + 1] = {rightBox, rightFirst, rightCount, 0};
      nodes_[ni].child = left;
      work.push_back({left + 1, left + 2 * (leftCount + leftSlack), slack - leftSlack, rightCent});
      work.push_back({left, left + 2, leftSlack, leftCent});
    };
    // Children whose bounds only a pass over their references can tell.
    auto addScannedChildren = [&](uint32_t leftCount, uint32_t rightCount, uint32_t slack) {
      Bounds3f lb, lc, rb, rc;
      Scan(node.first, node.first + leftCount, lb, lc);
      Scan(node.first + leftCount, node.first + leftCount + rightCount, rb, rc);
      addChildren(leftCount, lb, lc, rightCount, rb, rc, slack);
    };

    const bool exact = node.count <= kExactSplitMax;
    uint8_t order[kExactSplitMax];  // exact: the primitives in centroid order along best.axis
    Split best = exact ? FindExactSplit(node, order) : FindSplit(node, task.centroids, threads);
    // Spatial splits are tried where the object split leaves overlapping children (or
    // found no plane at all), while the node has slots for more references.
    SpatialSplit spatial;
    if (spatial_ && task.slack > 0) {
      const float overlap = best.axis >= 0 ? Intersection(best.left, best.right).SurfaceArea() : node.box.SurfaceArea();
      if (overlap > opt_.spatialOverlap * rootArea_) spatial = FindSpatialSplit(node);
    }
    const float leafCost = opt_.intersectionCost * float(node.count);
    if (node.count <= opt_.maxLeafSize && !(std::min(best.cost, spatial.cost) < leafCost)) return;
    if (spatial.cost < best.cost) {
      uint32_t leftCount = 0, rightCount = 0;
      if (SplitSpatially(node, spatial, task.slack, leftCount, rightCount))
        return addScannedChildren(leftCount, rightCount, task.slack - (leftCount + rightCount - node.count));
    }
    const uint32_t end = node.first + node.count;
    if (best.axis < 0) {
      // No usable plane (a flat node, or all centroids coincide): split at the median
      // along the widest centroid axis, which always makes progress and keeps leaves
      // within maxLeafSize.
      Bounds3f box, cent;
      Scan(node.first, end, box, cent);
      const glm::vec3 d = cent.Diagonal();
      const int a = d.x >= d.y && d.x >= d.z ? 0 : (d.y >= d.z ? 1 : 2);
      const uint32_t mid = node.first + node.count / 2;
      std::nth_element(prims_.begin() + node.first, prims_.begin() + mid, prims_.begin() + end, CentroidLess{a});
      return addScannedChildren(mid - node.first, end - mid, task.slack);
    }
    if (exact) {
      // best.bin primitives, in centroid order along the axis, go left.
      BuildPrim sorted[kExactSplitMax];
      for (uint32_t k = 0; k < node.count; ++k) sorted[k] = prims_[node.first + order[k]];
      std::copy(sorted, sorted + node.count, prims_.begin() + node.first);
      return addChildren(best.bin, best.left, {}, node.count - best.bin, best.right, {}, task.slack);
    }
    Bounds3f leftCent, rightCent;
    const uint32_t mid = PartitionByBin(node.first, end, task.centroids, best, threads, leftCent, rightCent);
    addChildren(mid - node.first, best.left, leftCent, end - mid, best.right, rightCent, task.slack);
  }

  // Moves the primitives of [b, e) whose centroid bin along `axis` is below `bin` to the
  // front (Hoare's two-pointer scheme) and returns where the right side starts; the
  // centroids of both sides are gathered into lc and rc on the way.
  uint32_t PartitionRange(uint32_t b, uint32_t e, const BinMap& map, int axis, int32_t bin, Bin& lc, Bin& rc) {
    uint32_t i = b, j = e;
    while (true) {
      Float4 ci = Splat4(0.0f), cj = ci;
      while (i < j && map.Of(ci = prims_[i].Centroid4())[axis] < bin) lc.Extend(ci, ci), ++i;
      while (i < j && map.Of(cj = prims_[j - 1].Centroid4())[axis] >= bin) rc.Extend(cj, cj), --j;
      if (i == j) return i;
      // prims_[i] goes right and prims_[j - 1] left.
      std::swap(prims_[i], prims_[j - 1]);
      lc.Extend(cj, cj), rc.Extend(ci, ci);
      ++i, --j;
    }
  }

  // Partitions [b, e) by best's plane (see PartitionRange). A large range is cut into
  // fixed blocks, each partitioned on its own (on all threads); then the right-side
  // primitives left of the final boundary trade places with the left-side primitives
  // right of it, pairwise in position order. The blocks do not depend on the thread
  // count, so neither does the resulting order.
  uint32_t PartitionByBin(uint32_t b, uint32_t e, const Bounds3f& centroids, const Split& best, unsigned threads,
                          Bounds3f& leftCent, Bounds3f& rightCent) {
    const BinMap map(centroids, opt_.bins);
    const int32_t bin = int32_t(best.bin);
    if (e - b < kParallelNode) {
      Bin lc, rc;
      const uint32_t mid = PartitionRange(b, e, map, best.axis, bin, lc, rc);
      leftCent = lc.Box(), rightCent = rc.Box();
      return mid;
    }
    constexpr uint32_t kBlock = 1u << 14;
    const uint32_t blocks = (e - b + kBlock - 1) / kBlock;
    std::vector<uint32_t> split(blocks);  // where each block's right side starts
    std::vector<Bin> lc(blocks), rc(blocks);
    ParallelFor(blocks, threads, [&](size_t k) {
      const uint32_t bb = b + uint32_t(k) * kBlock;
      split[k] = PartitionRange(bb, std::min(e, bb + kBlock), map, best.axis, bin, lc[k], rc[k]);
    });
    uint32_t mid = b;
    Bin left, right;
    for (uint32_t k = 0; k < blocks; ++k) {
      mid += split[k] - (b + k * kBlock);
      left.Extend(lc[k].lo, lc[k].hi), right.Extend(rc[k].lo, rc[k].hi);
    }
    leftCent = left.Box(), rightCent = right.Box();
    // The misplaced: right-side runs before mid and left-side runs after it, as
    // intervals in position order; both hold the same number of primitives.
    struct Run {
      uint32_t first, count;
    };
    std::vector<Run> wrongRight, wrongLeft;
    for (uint32_t k = 0; k < blocks; ++k) {
      const uint32_t bb = b + k * kBlock, be = std::min(e, bb + kBlock);
      const uint32_t rightEnd = std::min(be, mid), leftStart = std::max(bb, mid);
      if (split[k] < rightEnd) wrongRight.push_back({split[k], rightEnd - split[k]});
      if (split[k] > leftStart) wrongLeft.push_back({leftStart, split[k] - leftStart});
    }
    uint64_t misplaced = 0;
    for (const Run& r : wrongRight) misplaced += r.count;
    // Swap the i-th misplaced right with the i-th misplaced left, for i in one slice of
    // [0, misplaced) per thread.
    const unsigned slices = misplaced < kParallelNode ? 1u : threads;
    ParallelFor(slices, slices, [&](size_t t) {
      uint64_t i = misplaced * t / slices, end = misplaced * (t + 1) / slices;
      // Finds run and offset of the i-th element of `runs`.
      auto locate = [](const std::vector<Run>& runs, uint64_t i, size_t& run, uint32_t& offset) {
        for (run = 0; i >= runs[run].count; ++run) i -= runs[run].count;
        offset = uint32_t(i);
      };
      size_t rr, lr;
      uint32_t ro, lo;
      if (i == end) return;
      locate(wrongRight, i, rr, ro);
      locate(wrongLeft, i, lr, lo);
      for (; i < end; ++i) {
        std::swap(prims_[wrongRight[rr].first + ro], prims_[wrongLeft[lr].first + lo]);
        if (++ro == wrongRight[rr].count) ++rr, ro = 0;
        if (++lo == wrongLeft[lr].count) ++lr, lo = 0;
      }
    });
    return mid;
  }

  // The exact SAH split of a small node: every position in the centroid order along each
  // axis is a candidate (Split::bin = how many primitives go left). Costs as SweepBins.
  // `order` receives the node's primitives (offsets from node.first) in centroid order
  // along the chosen axis.
  Split FindExactSplit(const BuildNode& node, uint8_t order[kExactSplitMax]) const {
    Split best;
    const uint32_t n = node.count;
    const float parentArea = node.box.SurfaceArea();
    if (!(parentArea > 0.0f)) return best;  // a flat node: the caller's median split
    // Each primitive's rank along all three axes at once, by comparing every pair (the
    // order of CentroidLess): no data-dependent branches, unlike a sort of so few items.
    const BuildPrim* p = &prims_[node.first];
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
    uint8_t sorted[3][kExactSplitMax];
    for (uint32_t i = 0; i < n; ++i)
      for (int a = 0; a < 3; ++a) sorted[a][rank[i][a]] = uint8_t(i);
    Bin right[kExactSplitMax];
    int bestAxis = -1;
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
        const float cost = opt_.traversalCost + opt_.intersectionCost *
                                                    (acc.Area() * float(k) + right[k].Area() * float(n - k)) / parentArea;
        if (cost < best.cost) best = {a, k, cost, acc.Box(), right[k].Box()}, bestAxis = a;
      }
    }
    if (bestAxis >= 0) std::copy(sorted[bestAxis], sorted[bestAxis] + n, order);
    return best;
  }

  // --- Spatial splits -----------------------------------------------------------------
  // Spatial bin k of `axis` over the node's box spans [Plane(k), Plane(k + 1)).
  struct SpatialBins {
    float lo, scale, step;
    uint32_t count;
    uint32_t Of(float x) const { return std::min(count - 1, uint32_t(std::max(0.0f, (x - lo) * scale))); }
    float Plane(uint32_t k) const { return lo + float(k) * step; }
  };

  SpatialBins BinsOf(const BuildNode& node, int axis) const {
    const float extent = node.box.hi[axis] - node.box.lo[axis];
    return {node.box.lo[axis], float(opt_.bins) / extent, extent / float(opt_.bins), opt_.bins};
  }

  void Vertices(uint32_t prim, Float4 v[3]) const {
    for (int k = 0; k < 3; ++k) {
      const glm::vec3& p = verts_[3 * size_t(prim) + k];
      v[k] = Float4{p.x, p.y, p.z, 0.0f};
    }
  }

  // Every reference is counted where it enters (its first bin) and where it leaves (its
  // last), and the box of its part within each bin it spans goes into that bin; a plane's
  // cost then counts each side's references and their clipped bounds.
  SpatialSplit FindSpatialSplit(const BuildNode& node) const {
    SpatialSplit best;
    const float parentArea = node.box.SurfaceArea();
    if (!(parentArea > 0.0f)) return best;
    const uint32_t nb = opt_.bins;
    const float inf = std::numeric_limits<float>::infinity();
    static thread_local std::vector<Bin> bins;
    static thread_local std::vector<uint32_t> entries, exits;
    for (int a = 0; a < 3; ++a) {
      if (!(node.box.hi[a] > node.box.lo[a])) continue;
      const SpatialBins sb = BinsOf(node, a);
      bins.assign(nb, Bin{});
      entries.assign(nb, 0u);
      exits.assign(nb, 0u);
      for (uint32_t i = node.first; i < node.first + node.count; ++i) {
        const BuildPrim& p = prims_[i];
        const uint32_t b0 = sb.Of(p.box.lo[a]), b1 = sb.Of(p.box.hi[a]);
        ++entries[b0];
        ++exits[b1];
        if (b0 == b1) {
          bins[b0].Extend(Load4(&p.box.lo.x), Load4(&p.box.hi.x));
          continue;
        }
        // The part in each bin, cut to the reference's box. These boxes only estimate
        // costs (the split itself clips conservatively), so they are not padded.
        Float4 v[3];
        Vertices(p.index, v);
        const Float4 refLo = Load4(&p.box.lo.x), refHi = Load4(&p.box.hi.x);
        for (uint32_t b = b0; b <= b1; ++b) {
          Box4 part = ClipTriangle(v, a, b == b0 ? -inf : sb.Plane(b), b == b1 ? inf : sb.Plane(b + 1));
          part = {Max4(part.lo, refLo), Min4(part.hi, refHi)};
          if (!part.Empty()) bins[b].Extend(part.lo, part.hi);
        }
      }
      SweepBins(
          bins.data(), [&](uint32_t b) { return entries[b]; }, [&](uint32_t b) { return exits[b]; }, parentArea,
          [&](uint32_t b, float cost, const Bin& left, const Bin& right) {
            if (cost < best.cost) best = {a, b, cost, left, right};
          });
    }
    return best;
  }

  // Performs a spatial split of `node`: the left references, then the right ones, are
  // written from node.first on. A straddling reference is split in two clipped halves,
  // or "unsplit" — kept whole on one side — where that costs less (Stich et al. 2009,
  // §4.3: compare A_L·N_L + A_R·N_R with the whole reference added to either box and
  // dropped from the other count), and always once the node's `slack` free slots are
  // used up. False if one side would be empty.
  bool SplitSpatially(const BuildNode& node, const SpatialSplit& split, uint32_t slack, uint32_t& leftCount,
                      uint32_t& rightCount) {
    const int a = split.axis;
    const SpatialBins sb = BinsOf(node, a);
    const float plane = sb.Plane(split.bin), inf = std::numeric_limits<float>::infinity();
    Bounds3f boxL = split.left.Box(), boxR = split.right.Box();
    float nl = float(split.left.count), nr = float(split.right.count);
    std::vector<BuildPrim> left, right;
    for (uint32_t i = node.first; i < node.first + node.count; ++i) {
      const BuildPrim& p = prims_[i];
      const uint32_t b0 = sb.Of(p.box.lo[a]), b1 = sb.Of(p.box.hi[a]);
      if (b1 < split.bin) {
        left.push_back(p);
        continue;
      }
      if (b0 >= split.bin) {
        right.push_back(p);
        continue;
      }
      Float4 v[3];
      Vertices(p.index, v);
      const Bounds3f l = Conservative(ClipTriangle(v, a, -inf, plane), p.box);
      const Bounds3f r = Conservative(ClipTriangle(v, a, plane, inf), p.box);
      if (l.Empty() || r.Empty()) {  // all on one side after all
        (l.Empty() ? right : left).push_back(p);
        continue;
      }
      Bounds3f wholeL = boxL, wholeR = boxR;
      wholeL.Extend(p.box);
      wholeR.Extend(p.box);
      const float costSplit = slack > 0 ? boxL.SurfaceArea() * nl + boxR.SurfaceArea() * nr : inf;
      const float costLeft = wholeL.SurfaceArea() * nl + boxR.SurfaceArea() * (nr - 1.0f);
      const float costRight = boxL.SurfaceArea() * (nl - 1.0f) + wholeR.SurfaceArea() * nr;
      if (costSplit <= costLeft && costSplit <= costRight) {
        --slack;
        left.push_back({l, p.index});
        right.push_back({r, p.index});
      } else if (costLeft <= costRight) {
        left.push_back(p);
        boxL = wholeL;
        nr -= 1.0f;
      } else {
        right.push_back(p);
        boxR = wholeR;
        nl -= 1.0f;
      }
    }
    if (left.empty() || right.empty()) return false;
    std::copy(left.begin(), left.end(), prims_.begin() + node.first);
    std::copy(right.begin(), right.end(), prims_.begin() + node.first + left.size());
    leftCount = uint32_t(left.size());
    rightCount = uint32_t(right.size());
    return true;
  }

  // Spatial splits leave unused slots in prims_; this packs the leaves' references in
  // depth-first order (so the triangle array follows the tree, as without splits).
  void CompactReferences() {
    HugeVector<BuildPrim> packed;
    packed.reserve(prims_.size());
    std::vector<uint32_t> stack{0};
    while (!stack.empty()) {
      BuildNode& n = nodes_[stack.back()];
      stack.pop_back();
      if (!n.IsLeaf()) {
        stack.insert(stack.end(), {n.child + 1, n.child});
        continue;
      }
      packed.insert(packed.end(), prims_.begin() + n.first, prims_.begin() + n.first + n.count);
      n.first = uint32_t(packed.size() - n.count);
    }
    prims_ = std::move(packed);
  }

  Split FindSplit(const BuildNode& node, const Bounds3f& centroids, unsigned threads) const {
    Split best;
    const float parentArea = node.box.SurfaceArea();
    const uint32_t nb = opt_.bins;
    const BinMap map(centroids, nb);
    // One pass over the primitives bins all three axes (bins [a·nb, (a+1)·nb)). Each
    // thread fills its own scratch bins, reused across calls (no allocation per node);
    // merging min/max and counts is exact, so the result does not depend on `threads`.
    auto binRange = [&](uint32_t b, uint32_t e, std::vector<Bin>& out) {
      out.assign(3 * nb, Bin{});
      for (uint32_t i = b; i < e; ++i) {
        const BuildPrim& p = prims_[i];
        const Int4 k = map.Of(p.Centroid4());
        const Float4 boxLo = Load4(&p.box.lo.x), boxHi = Load4(&p.box.hi.x);
        for (int a = 0; a < 3; ++a) {
          Bin& bin = out[a * nb + uint32_t(k[a])];
          bin.Extend(boxLo, boxHi);
          ++bin.count;
        }
      }
    };
    static thread_local std::vector<Bin> scratch;
    std::vector<Bin> merged;
    const std::vector<Bin>* all = &scratch;
    if (threads == 1) {
      binRange(node.first, node.first + node.count, scratch);
    } else {
      std::vector<std::vector<Bin>> partial(threads);
      ForChunks(node.first, node.count, threads, [&](uint32_t b, uint32_t e, unsigned t) { binRange(b, e, partial[t]); });
      merged.assign(3 * nb, Bin{});
      for (const std::vector<Bin>& mine : partial)
        for (uint32_t k = 0; k < 3 * nb; ++k) merged[k].Merge(mine[k]);
      all = &merged;
    }
    for (int a = 0; a < 3; ++a) {
      if (!map.Usable(a)) continue;
      const Bin* bins = all->data() + a * nb;
      auto count = [&](uint32_t b) { return bins[b].count; };
      SweepBins(bins, count, count, parentArea, [&](uint32_t b, float cost, const Bin& left, const Bin& right) {
        if (cost < best.cost) best = {a, b, cost, left.Box(), right.Box()};
      });
    }
    // A flat parent (zero area) makes every cost NaN or ∞: fall back to the median split.
    if (!(parentArea > 0.0f)) best.axis = -1, best.cost = std::numeric_limits<float>::infinity();
    return best;
  }

  BvhBuildOptions opt_;
  std::span<const glm::vec3> verts_;  // three per primitive (spatial splits)
  bool spatial_ = false;
  uint32_t duplicationBudget_ = 0;  // references spatial splits may add in all
  unsigned threads_ = 1;
  float rootArea_ = 0.0f;
  Bounds3f rootCentroids_;
  HugeVector<BuildPrim> prims_;
  HugeVector<BuildNode> nodes_;
};

}  // namespace

Bvh BuildBvh(std::span<const Bounds3f> primBounds, const BvhBuildOptions& options,
             std::span<const glm::vec3> vertices) {
  if (primBounds.empty()) throw Error("cannot build a BVH over zero primitives");
  if (options.maxLeafSize < 1 || options.maxLeafSize > shader::kMaxLeafSize)
    throw Error("BVH leaf size must be in [1, " + std::to_string(shader::kMaxLeafSize) + "]");
  if (options.bins < 2 || options.bins > 256) throw Error("BVH bin count must be in [2, 256]");
  if (primBounds.size() >= (1u << 28)) throw Error("too many triangles for the BVH layout (limit 2^28)");
  if (!vertices.empty() && vertices.size() != 3 * primBounds.size())
    throw Error("BVH build: expected three vertices per primitive");
  if (!(options.maxDuplication >= 0.0f)) throw Error("BVH build: the duplication budget must be >= 0");
  auto t0 = std::chrono::steady_clock::now();
  const bool spatial = options.splits != SplitMode::kObject && !vertices.empty();
  const std::span<const glm::vec3> noVertices;
  TreeLayout tree = Builder(primBounds, options, spatial ? vertices : noVertices).Build();
  bool keptSpatial = spatial;
  double rejectedSahCost = 0.0;
  if (spatial && options.splits == SplitMode::kAuto) {
    // The trees are compared as measured for their layout (the SAH comes from there);
    // only the one kept is written. A tie goes to the object tree: as fast, with no
    // duplicated references. So does a spatial tree too big for its direction-ordered
    // copies when the object tree has them: a fixed traversal order costs diffuse rays
    // ~24 % more box tests and ~40 % more triangle tests, more than spatial splits save
    // (1–21 % of the SAH on the corpus).
    TreeLayout objectOnly = Builder(primBounds, options, noVertices).Build();
    const bool keepObject = objectOnly.Copies() != tree.Copies()
                                ? objectOnly.Copies() > tree.Copies()
                                : objectOnly.Stats().sahCost <= tree.Stats().sahCost;
    rejectedSahCost = (keepObject ? tree : objectOnly).Stats().sahCost;
    if (keepObject) tree = std::move(objectOnly), keptSpatial = false;
  }
  Bvh bvh = tree.Write();
  bvh.stats.spatialSplits = keptSpatial;
  bvh.stats.rejectedSahCost = rejectedSahCost;
  bvh.stats.buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return bvh;
}

}  // namespace vkpt

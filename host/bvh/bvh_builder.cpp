// Binned SAH builder (Wald 2007, "On fast Construction of SAH-based Bounding Volume
// Hierarchies"): primitives are binned by centroid along each axis, the split plane with
// the lowest surface-area-heuristic cost wins, and a node becomes a leaf when splitting
// would not pay. The tree is built into a temporary array and then flattened into the
// depth-first skip-link layout; the builder is iterative, so a pathological input
// cannot overflow the call stack.
#include <algorithm>
#include <array>
#include <atomic>
#include <thread>
#include <chrono>
#include <cstddef>
#include <limits>

#include "bvh/bvh.h"
#include "util/float4.h"
#include "util/huge_pages.h"
#include "util/error.h"

namespace vkpt {
namespace {

// 32 bytes, laid out so that 16-byte loads at box.lo and box.hi give x, y, z in lanes 0-2
// (lane 3 holds the next field and is ignored). The centroid is not stored: it is
// (lo + hi) / 2, computed where needed exactly as Bounds3f::Center does; every pass over
// the primitives then moves a fifth less memory.
struct BuildPrim {
  Bounds3f box;
  uint32_t index;
  uint32_t pad = 0;

  float Centroid(int axis) const { return (box.lo[axis] + box.hi[axis]) * 0.5f; }
  Float4 Centroid4() const { return (Load4(&box.lo.x) + Load4(&box.hi.x)) * Splat4(0.5f); }
};
static_assert(sizeof(BuildPrim) == 32 && offsetof(Bounds3f, hi) == 12);

// Orders primitives by centroid along `axis`, ties by index (so the order is unique).
struct CentroidLess {
  int axis;
  bool operator()(const BuildPrim& p, const BuildPrim& q) const {
    const float cp = p.Centroid(axis), cq = q.Centroid(axis);
    return cp < cq || (cp == cq && p.index < q.index);
  }
};

struct BuildNode {
  Bounds3f box;
  uint32_t first = 0, count = 0;          // leaf: primitive range in `prims`
  uint32_t child[2] = {0, 0};             // inner: indices into the BuildNode array
  uint32_t depth = 0;
  bool leaf = false;
};
using NodeArray = HugeVector<BuildNode>;

// A bin's box in lanes 0-2 of lo and hi; lane 3 is whatever the primitives carried.
struct Bin {
  Float4 lo = Splat4(std::numeric_limits<float>::infinity());
  Float4 hi = Splat4(-std::numeric_limits<float>::infinity());
  uint32_t count = 0;

  void Extend(Float4 boxLo, Float4 boxHi) {
    lo = Min4(lo, boxLo);
    hi = Max4(hi, boxHi);
  }
  Bounds3f Box() const { return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}; }
  // Bounds3f::SurfaceArea of Box(), for a bin that holds something.
  float Area() const {
    Float4 d = hi - lo;
    return 2.0f * (d[0] * d[1] + d[1] * d[2] + d[2] * d[0]);
  }
};

// Nodes with at least this many primitives are binned on several threads.
constexpr uint32_t kParallelNode = 1u << 15;

// A small node is split exactly: every position in its centroid order is costed.
constexpr uint32_t kExactSplitMax = 8;

// A node waiting to be split, with its centroids' bounds (binning needs them).
struct Task {
  uint32_t node;
  Bounds3f centroids;
};

// Centroid → bin index along all three axes at once: nb bins spanning the node's
// centroid bounds. Binning and partitioning both use it, so they agree to the last bit.
// An axis with no centroid extent has scale 0: everything lands in bin 0 and the sweep
// skips the axis.
struct BinMap {
  Float4 lo, scale;
  Int4 last;
  BinMap(const Bounds3f& centroids, uint32_t nb) {
    float s[3];
    for (int a = 0; a < 3; ++a) {
      const float extent = centroids.hi[a] - centroids.lo[a];
      s[a] = extent > 0.0f ? float(nb) / extent : 0.0f;
    }
    lo = Float4{centroids.lo.x, centroids.lo.y, centroids.lo.z, 0.0f};
    scale = Float4{s[0], s[1], s[2], 0.0f};
    last = Int4{1, 1, 1, 1} * int32_t(nb - 1);
  }
  bool Usable(int axis) const { return scale[axis] > 0.0f; }
  Int4 Of(Float4 centroid) const {
    const Int4 k = __builtin_convertvector(Max4((centroid - lo) * scale, Splat4(0.0f)), Int4);
    return k < last ? k : last;
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
};

Bounds3f Intersection(const Bounds3f& a, const Bounds3f& b) {
  Bounds3f r;
  r.lo = glm::max(a.lo, b.lo);
  r.hi = glm::min(a.hi, b.hi);
  return r;
}

// Bounds of the part of triangle v[0..2] with lo <= p[axis] <= hi: the vertices inside
// the slab and the points where edges cross its planes. Rounding in the crossings could
// shave the box, so it is padded by a few ulps of its coordinates; the caller intersects
// it with the reference's box, which stays conservative.
Bounds3f ClipTriangle(const glm::vec3 v[3], int axis, float lo, float hi) {
  Bounds3f b;
  for (int i = 0; i < 3; ++i) {
    const glm::vec3 p = v[i], q = v[(i + 1) % 3];
    const float pa = p[axis], qa = q[axis];
    if (pa >= lo && pa <= hi) b.Extend(p);
    for (float plane : {lo, hi}) {
      if ((pa < plane && qa > plane) || (pa > plane && qa < plane)) {
        glm::vec3 x = p + (q - p) * ((plane - pa) / (qa - pa));
        x[axis] = plane;
        b.Extend(x);
      }
    }
  }
  if (b.Empty()) return b;
  const glm::vec3 pad = (glm::abs(b.lo) + glm::abs(b.hi)) * 4e-7f + glm::vec3(1e-30f);
  b.lo -= pad;
  b.hi += pad;
  return b;
}

class Builder {
 public:
  Builder(std::span<const Bounds3f> bounds, const BvhBuildOptions& o, std::span<const glm::vec3> vertices)
      : opt_(o), verts_(vertices), spatial_(o.spatialSplits && vertices.size() == 3 * bounds.size()) {
    prims_.reserve(bounds.size());
    for (uint32_t i = 0; i < bounds.size(); ++i)
      prims_.push_back({bounds[i], i});
    // References stay below 2^28, what a leaf code can address.
    duplicatesLeft_ = spatial_ ? std::min<uint64_t>(uint64_t(double(o.maxDuplication) * double(bounds.size())),
                                                    (1u << 28) - 1 - bounds.size())
                               : 0;
  }

  Bvh Build() {
    // Spatial splits append references to prims_ as they go: one thread.
    const unsigned threads =
        spatial_ ? 1u : opt_.threads ? opt_.threads : std::max(1u, std::thread::hardware_concurrency());
    nodes_.reserve(2 * prims_.size());  // a binary tree over n leaves' worth has < 2n nodes
    nodes_.push_back({});
    nodes_[0].count = uint32_t(prims_.size());
    // The root's box and centroid bounds; every other node gets them from its parent.
    Task root{0, {}};
    {
      std::vector<Bounds3f> boxes(threads), cents(threads);
      ForChunks(0, nodes_[0].count, threads, [&](uint32_t b, uint32_t e, unsigned t) { Scan(b, e, boxes[t], cents[t]); });
      for (unsigned t = 0; t < threads; ++t) {
        nodes_[0].box.Extend(boxes[t]);
        root.centroids.Extend(cents[t]);
      }
    }
    rootArea_ = nodes_[0].box.SurfaceArea();
    // Phase 1, top levels: one node at a time, its binning spread over all threads.
    // Nodes below `small` primitives are deferred as independent subtrees.
    const uint32_t small = threads > 1 ? std::max(4096u, uint32_t(prims_.size() / (8 * threads))) : 0u;
    std::vector<Task> work{root}, deferred;
    while (!work.empty()) {
      Task task = work.back();
      work.pop_back();
      if (nodes_[task.node].count < small) deferred.push_back(task);
      else Subdivide(nodes_, task, work, threads);
    }
    // Phase 2: the subtrees, one per thread at a time, each into its own node array;
    // they touch disjoint ranges of prims_. The tree does not depend on the thread
    // count (only the order of nodes_ does, which Flatten does not see).
    std::vector<NodeArray> subtrees(deferred.size());
    std::atomic<size_t> next{0};
    auto worker = [&] {
      for (size_t k; (k = next.fetch_add(1)) < deferred.size();) {
        NodeArray& local = subtrees[k];
        local.push_back(nodes_[deferred[k].node]);
        std::vector<Task> localWork{{0, deferred[k].centroids}};
        while (!localWork.empty()) {
          Task task = localWork.back();
          localWork.pop_back();
          Subdivide(local, task, localWork, 1);
        }
      }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < std::min<size_t>(threads, deferred.size()); ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    // Stitch: subtree k's local node j >= 1 goes to offset[k] + j, its local node 0
    // replaces its root. The offsets follow k, so the result does not depend on which
    // thread copies what; the copies (a serial half second for 1 M triangles) run on all
    // threads.
    std::vector<uint32_t> offset(deferred.size());
    size_t total = nodes_.size();
    for (size_t k = 0; k < deferred.size(); ++k) {
      offset[k] = uint32_t(total) - 1;
      total += subtrees[k].size() - 1;
    }
    nodes_.resize(total);
    next = 0;
    auto stitch = [&] {
      for (size_t k; (k = next.fetch_add(1)) < deferred.size();) {
        NodeArray local = std::move(subtrees[k]);
        for (BuildNode& n : local)
          if (!n.leaf) n.child[0] += offset[k], n.child[1] += offset[k];
        nodes_[deferred[k].node] = local[0];
        std::copy(local.begin() + 1, local.end(), nodes_.begin() + offset[k] + 1);
      }
    };
    pool.clear();
    for (unsigned t = 1; t < std::min<size_t>(threads, deferred.size()); ++t) pool.emplace_back(stitch);
    stitch();
    for (auto& t : pool) t.join();
    if (spatial_) CompactReferences();
    return Flatten();
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
      float cost = opt_.traversalCost +
                   opt_.intersectionCost * (acc.Area() * float(acc.count) + right[b].Area() * float(right[b].count)) /
                       parentArea;
      consider(b, cost, acc, right[b]);
    }
  }

  // Runs f(begin, end, chunk) over [first, first + count) split into `threads` chunks.
  template <class F>
  static void ForChunks(uint32_t first, uint32_t count, unsigned threads, F&& f) {
    std::vector<std::thread> pool;
    const uint32_t per = (count + threads - 1) / threads;
    for (unsigned t = 1; t < threads; ++t) {
      uint32_t b = first + std::min(count, t * per), e = first + std::min(count, (t + 1) * per);
      pool.emplace_back([&f, b, e, t] { f(b, e, t); });
    }
    f(first, first + std::min(count, per), 0u);
    for (auto& th : pool) th.join();
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

  // Splits the node of `task` in `nodes` (or makes it a leaf), appending its children to
  // `nodes` and `work`. The node's box is set; large nodes are binned on `threads` threads.
  void Subdivide(NodeArray& nodes, const Task& task, std::vector<Task>& work, unsigned threads) {
    const uint32_t ni = task.node;
    const BuildNode node = nodes[ni];
    if (node.count < kParallelNode) threads = 1;
    if (node.count == 1) {
      nodes[ni].leaf = true;
      return;
    }
    // Children take their boxes from the split (the union of their primitives' boxes,
    // whichever way it was found) and their centroid bounds from the pass that puts
    // their primitives in place; small children need none.
    auto addChildren = [&](uint32_t leftFirst, uint32_t leftCount, const Bounds3f& leftBox, const Bounds3f& leftCent,
                           uint32_t rightFirst, uint32_t rightCount, const Bounds3f& rightBox, const Bounds3f& rightCent) {
      uint32_t left = uint32_t(nodes.size());
      BuildNode l, r;
      l.box = leftBox;
      l.first = leftFirst;
      l.count = leftCount;
      r.box = rightBox;
      r.first = rightFirst;
      r.count = rightCount;
      l.depth = r.depth = node.depth + 1;
      nodes.push_back(l);
      nodes.push_back(r);
      nodes[ni].child[0] = left;
      nodes[ni].child[1] = left + 1;
      work.push_back({left + 1, rightCent});
      work.push_back({left, leftCent});
    };
    // Children whose bounds only a pass over their primitives can tell.
    auto addScannedChildren = [&](uint32_t leftFirst, uint32_t leftCount, uint32_t rightFirst, uint32_t rightCount) {
      Bounds3f lb, lc, rb, rc;
      Scan(leftFirst, leftFirst + leftCount, lb, lc);
      Scan(rightFirst, rightFirst + rightCount, rb, rc);
      addChildren(leftFirst, leftCount, lb, lc, rightFirst, rightCount, rb, rc);
    };

    const bool exact = node.count <= kExactSplitMax;
    Split best = exact ? FindExactSplit(node) : FindSplit(node, task.centroids, threads);
    // Spatial splits are tried where the object split leaves overlapping children (or
    // found no plane at all), while the duplication budget lasts.
    SpatialSplit spatial;
    if (spatial_ && duplicatesLeft_ > 0) {
      const float overlap = best.axis >= 0 ? Intersection(best.left, best.right).SurfaceArea() : node.box.SurfaceArea();
      if (overlap > opt_.spatialOverlap * rootArea_) spatial = FindSpatialSplit(node);
    }
    const float leafCost = opt_.intersectionCost * float(node.count);
    if (node.count <= opt_.maxLeafSize && !(std::min(best.cost, spatial.cost) < leafCost)) {
      nodes[ni].leaf = true;
      return;
    }
    if (spatial.cost < best.cost) {
      uint32_t leftCount = 0, rightFirst = 0, rightCount = 0;
      if (SplitSpatially(node, spatial, leftCount, rightFirst, rightCount))
        return addScannedChildren(node.first, leftCount, rightFirst, rightCount);
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
      return addScannedChildren(node.first, mid - node.first, mid, end - mid);
    }
    if (exact) {
      // best.bin primitives, in centroid order along the axis, go left.
      SortByCentroid(node.first, end, best.axis);
      return addChildren(node.first, best.bin, best.left, {}, node.first + best.bin, node.count - best.bin, best.right, {});
    }
    Bounds3f leftCent, rightCent;
    const uint32_t mid = PartitionByBin(node.first, end, task.centroids, best, leftCent, rightCent);
    addChildren(node.first, mid - node.first, best.left, leftCent, mid, end - mid, best.right, rightCent);
  }

  // Insertion sort of prims_[b, e): a few primitives, so no call overhead.
  void SortByCentroid(uint32_t b, uint32_t e, int axis) {
    const CentroidLess less{axis};
    for (uint32_t i = b + 1; i < e; ++i) {
      const BuildPrim p = prims_[i];
      uint32_t j = i;
      for (; j > b && less(p, prims_[j - 1]); --j) prims_[j] = prims_[j - 1];
      prims_[j] = p;
    }
  }

  // Moves the primitives of [b, e) whose centroid bin along best.axis is below best.bin
  // to the front (Hoare's two-pointer scheme) and returns where the right side starts;
  // the centroid bounds of both sides are gathered on the way.
  uint32_t PartitionByBin(uint32_t b, uint32_t e, const Bounds3f& centroids, const Split& best, Bounds3f& leftCent,
                          Bounds3f& rightCent) {
    const BinMap map(centroids, opt_.bins);
    const int a = best.axis;
    const int32_t bin = int32_t(best.bin);
    Bin lc, rc;
    uint32_t i = b, j = e;
    while (true) {
      Float4 ci = Splat4(0.0f), cj = ci;
      while (i < j && map.Of(ci = prims_[i].Centroid4())[a] < bin) lc.Extend(ci, ci), ++i;
      while (i < j && map.Of(cj = prims_[j - 1].Centroid4())[a] >= bin) rc.Extend(cj, cj), --j;
      if (i == j) break;
      // prims_[i] goes right and prims_[j - 1] left.
      std::swap(prims_[i], prims_[j - 1]);
      lc.Extend(cj, cj), rc.Extend(ci, ci);
      ++i, --j;
    }
    leftCent = lc.Box();
    rightCent = rc.Box();
    return i;
  }

  // The exact SAH split of a small node: every position in the centroid order along each
  // axis is a candidate (Split::bin = how many primitives go left). Costs as SweepBins.
  Split FindExactSplit(const BuildNode& node) const {
    Split best;
    const uint32_t n = node.count;
    const float parentArea = node.box.SurfaceArea();
    if (!(parentArea > 0.0f)) return best;  // a flat node: the caller's median split
    BuildPrim sorted[kExactSplitMax];
    Bin right[kExactSplitMax];
    for (int a = 0; a < 3; ++a) {
      std::copy(prims_.begin() + node.first, prims_.begin() + node.first + n, sorted);
      const CentroidLess less{a};
      for (uint32_t i = 1; i < n; ++i) {
        const BuildPrim p = sorted[i];
        uint32_t j = i;
        for (; j > 0 && less(p, sorted[j - 1]); --j) sorted[j] = sorted[j - 1];
        sorted[j] = p;
      }
      Bin acc;
      for (uint32_t k = n - 1; k > 0; --k) {
        acc.Extend(Load4(&sorted[k].box.lo.x), Load4(&sorted[k].box.hi.x));
        right[k] = acc;
      }
      acc = Bin{};
      for (uint32_t k = 1; k < n; ++k) {
        acc.Extend(Load4(&sorted[k - 1].box.lo.x), Load4(&sorted[k - 1].box.hi.x));
        const float cost = opt_.traversalCost + opt_.intersectionCost *
                                                    (acc.Area() * float(k) + right[k].Area() * float(n - k)) / parentArea;
        if (cost < best.cost) best = {a, k, cost, acc.Box(), right[k].Box()};
      }
    }
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

  void Vertices(uint32_t prim, glm::vec3 v[3]) const {
    for (int k = 0; k < 3; ++k) v[k] = verts_[3 * size_t(prim) + k];
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
        glm::vec3 v[3];
        Vertices(p.index, v);
        for (uint32_t b = b0; b <= b1; ++b) {
          Bounds3f part = Intersection(ClipTriangle(v, a, b == b0 ? -inf : sb.Plane(b), b == b1 ? inf : sb.Plane(b + 1)), p.box);
          if (!part.Empty()) bins[b].Extend(Float4{part.lo.x, part.lo.y, part.lo.z, 0.0f}, Float4{part.hi.x, part.hi.y, part.hi.z, 0.0f});
        }
      }
      SweepBins(
          bins.data(), [&](uint32_t b) { return entries[b]; }, [&](uint32_t b) { return exits[b]; }, parentArea,
          [&](uint32_t b, float cost, const Bin&, const Bin&) {
            if (cost < best.cost) best = {a, b, cost};
          });
    }
    return best;
  }

  // Performs a spatial split of `node`: its left references stay in place (there are
  // at most as many), the right ones are appended to prims_; a straddling reference goes
  // to both sides with its clipped bounds. False if one side would be empty.
  bool SplitSpatially(const BuildNode& node, const SpatialSplit& split, uint32_t& leftCount, uint32_t& rightFirst,
                      uint32_t& rightCount) {
    const int a = split.axis;
    const SpatialBins sb = BinsOf(node, a);
    const float plane = sb.Plane(split.bin), inf = std::numeric_limits<float>::infinity();
    std::vector<BuildPrim> left, right;
    for (uint32_t i = node.first; i < node.first + node.count; ++i) {
      const BuildPrim& p = prims_[i];
      const uint32_t b0 = sb.Of(p.box.lo[a]), b1 = sb.Of(p.box.hi[a]);
      if (b1 < split.bin) {
        left.push_back(p);
      } else if (b0 >= split.bin) {
        right.push_back(p);
      } else {
        glm::vec3 v[3];
        Vertices(p.index, v);
        Bounds3f l = Intersection(ClipTriangle(v, a, -inf, plane), p.box);
        Bounds3f r = Intersection(ClipTriangle(v, a, plane, inf), p.box);
        if (l.Empty() || (duplicatesLeft_ == 0 && !r.Empty())) {
          right.push_back(r.Empty() ? p : BuildPrim{r, p.index});
        } else if (r.Empty()) {
          left.push_back({l, p.index});
        } else {
          --duplicatesLeft_;
          left.push_back({l, p.index});
          right.push_back({r, p.index});
        }
      }
    }
    if (left.empty() || right.empty()) return false;
    std::copy(left.begin(), left.end(), prims_.begin() + node.first);
    leftCount = uint32_t(left.size());
    rightFirst = uint32_t(prims_.size());
    rightCount = uint32_t(right.size());
    prims_.insert(prims_.end(), right.begin(), right.end());
    return true;
  }

  // Spatial splits leave unused slots in prims_; this packs the leaves' references in
  // depth-first order (so the triangle array follows the tree, as without splits).
  void CompactReferences() {
    HugeVector<BuildPrim> packed;
    std::vector<uint32_t> stack{0};
    while (!stack.empty()) {
      BuildNode& n = nodes_[stack.back()];
      stack.pop_back();
      if (!n.leaf) {
        stack.insert(stack.end(), {n.child[1], n.child[0]});
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
        for (uint32_t k = 0; k < 3 * nb; ++k) {
          merged[k].Extend(mine[k].lo, mine[k].hi);
          merged[k].count += mine[k].count;
        }
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

  Bvh Flatten() const {
    // Subtree sizes, bottom-up: children always come after their parent in nodes_.
    HugeVector<uint32_t> size(nodes_.size(), 1);
    for (size_t i = nodes_.size(); i-- > 0;)
      if (!nodes_[i].leaf) size[i] = 1 + size[nodes_[i].child[0]] + size[nodes_[i].child[1]];

    Bvh bvh;
    // Partitioning kept every subtree's primitives contiguous in prims_, so a leaf's
    // range [first, first + count) is valid in every child order.
    bvh.primOrder.reserve(prims_.size());
    for (const BuildPrim& p : prims_) bvh.primOrder.push_back(p.index);
    const uint32_t count = uint32_t(nodes_.size());
    bvh.copies = opt_.directionCopies && uint64_t(count) * sizeof(shader::BvhNode) * 8 <= opt_.maxCopiesBytes ? 8 : 1;
    bvh.nodes.resize(size_t(count) * bvh.copies);
    // The copies fill disjoint ranges of bvh.nodes: one thread each.
    // (Small trees: a thread costs more than the copy.)
    const unsigned threads = count < 16384 ? 1u : std::min<unsigned>(bvh.copies, opt_.threads ? opt_.threads : std::max(1u, std::thread::hardware_concurrency()));
    std::atomic<uint32_t> nextCopy{0};
    auto flatten = [&] {
      for (uint32_t octant; (octant = nextCopy.fetch_add(1)) < bvh.copies;) FlattenCopy(size, octant, bvh);
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(flatten);
    flatten();
    for (auto& t : pool) t.join();
    BvhStats& st = bvh.stats;
    const float rootArea = nodes_[0].box.SurfaceArea();
    // Summed in depth-first order from the root (not storage order, which depends on the
    // thread count), so the reported cost is the same to the last bit for any count.
    std::vector<uint32_t> order{0};
    while (!order.empty()) {
      const BuildNode& n = nodes_[order.back()];
      order.pop_back();
      if (!n.leaf) order.insert(order.end(), {n.child[1], n.child[0]});
      // Relative area; a flat scene (root area 0) counts every node as 1.
      double rel = rootArea > 0.0f ? double(n.box.SurfaceArea()) / rootArea : 1.0;
      st.depth = std::max(st.depth, n.depth);
      if (n.leaf) {
        ++st.leaves;
        st.maxLeafPrims = std::max(st.maxLeafPrims, n.count);
        st.sahCost += rel * opt_.intersectionCost * n.count;
      } else {
        st.sahCost += rel * opt_.traversalCost;
      }
    }
    st.nodes = count;
    st.references = uint32_t(prims_.size());
    return bvh;
  }

  // Writes copy `octant` of the tree at nodes[octant * count ...], depth first, each
  // inner node's children ordered near-first for rays whose direction signs are the
  // octant's (bit 0: x < 0, bit 1: y < 0, bit 2: z < 0). Skip links are absolute.
  void FlattenCopy(const HugeVector<uint32_t>& size, uint32_t octant, Bvh& bvh) const {
    const uint32_t base = octant * uint32_t(nodes_.size());
    struct Item { uint32_t node, flat, skip; };
    std::vector<Item> stack{{0, base, shader::kInvalidIndex}};
    while (!stack.empty()) {
      Item it = stack.back();
      stack.pop_back();
      const BuildNode& n = nodes_[it.node];
      shader::BvhNode& out = bvh.nodes[it.flat];
      out.lo = n.box.lo;
      out.hi = n.box.hi;
      out.skip = it.skip;
      if (n.leaf) {
        out.leaf = (n.first << 4) | n.count;
        continue;
      }
      out.leaf = 0;
      // Near child first along the axis where the children's centres differ most.
      uint32_t first = n.child[0], second = n.child[1];
      glm::vec3 d = nodes_[second].box.Center() - nodes_[first].box.Center();
      glm::vec3 ad = glm::abs(d);
      int axis = ad.x >= ad.y && ad.x >= ad.z ? 0 : (ad.y >= ad.z ? 1 : 2);
      bool negative = (octant >> axis) & 1u;
      if ((d[axis] < 0.0f) != negative) std::swap(first, second);
      uint32_t secondFlat = it.flat + 1 + size[first];
      stack.push_back({second, secondFlat, it.skip});
      stack.push_back({first, it.flat + 1, secondFlat});
    }
  }

  BvhBuildOptions opt_;
  std::span<const glm::vec3> verts_;  // three per primitive (spatial splits)
  bool spatial_ = false;
  uint64_t duplicatesLeft_ = 0;  // references spatial splits may still add
  float rootArea_ = 0.0f;
  HugeVector<BuildPrim> prims_;
  NodeArray nodes_;
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
  Bvh bvh = Builder(primBounds, options, vertices).Build();
  bvh.stats.buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return bvh;
}

}  // namespace vkpt

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
#include "util/error.h"

namespace vkpt {
namespace {

// Laid out so that 16-byte loads at box.lo, box.hi and centroid give x, y, z in lanes
// 0-2 (lane 3 holds the next field and is ignored).
struct BuildPrim {
  Bounds3f box;
  glm::vec3 centroid;
  uint32_t index;
};
static_assert(offsetof(BuildPrim, box) == 0 && offsetof(Bounds3f, hi) == 12 && offsetof(BuildPrim, centroid) == 24);

struct BuildNode {
  Bounds3f box;
  uint32_t first = 0, count = 0;          // leaf: primitive range in `prims`
  uint32_t child[2] = {0, 0};             // inner: indices into the BuildNode array
  uint32_t depth = 0;
  bool leaf = false;
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
  Bounds3f Box() const { return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}; }
  // Bounds3f::SurfaceArea of Box(), for a bin that holds something.
  float Area() const {
    Float4 d = hi - lo;
    return 2.0f * (d[0] * d[1] + d[1] * d[2] + d[2] * d[0]);
  }
};

// Nodes with at least this many primitives are binned on several threads.
constexpr uint32_t kParallelNode = 1u << 15;

struct Split {
  int axis = -1;
  uint32_t bin = 0;  // primitives with bin index < `bin` go left
  float cost = std::numeric_limits<float>::infinity();
};

class Builder {
 public:
  Builder(std::span<const Bounds3f> bounds, const BvhBuildOptions& o) : opt_(o) {
    prims_.reserve(bounds.size());
    for (uint32_t i = 0; i < bounds.size(); ++i)
      prims_.push_back({bounds[i], bounds[i].Center(), i});
  }

  Bvh Build() {
    const unsigned threads = opt_.threads ? opt_.threads : std::max(1u, std::thread::hardware_concurrency());
    nodes_.reserve(2 * prims_.size() / std::max(1u, opt_.maxLeafSize) + 1);
    nodes_.push_back({});
    nodes_[0].count = uint32_t(prims_.size());
    // Phase 1, top levels: one node at a time, its binning spread over all threads.
    // Nodes below `small` primitives are deferred as independent subtrees.
    const uint32_t small = threads > 1 ? std::max(4096u, uint32_t(prims_.size() / (8 * threads))) : 0u;
    std::vector<uint32_t> work{0}, deferred;
    while (!work.empty()) {
      uint32_t n = work.back();
      work.pop_back();
      if (nodes_[n].count < small) deferred.push_back(n);
      else Subdivide(nodes_, n, work, threads);
    }
    // Phase 2: the subtrees, one per thread at a time, each into its own node array;
    // they touch disjoint ranges of prims_. The tree does not depend on the thread
    // count (only the order of nodes_ does, which Flatten does not see).
    std::vector<std::vector<BuildNode>> subtrees(deferred.size());
    std::atomic<size_t> next{0};
    auto worker = [&] {
      for (size_t k; (k = next.fetch_add(1)) < deferred.size();) {
        std::vector<BuildNode>& local = subtrees[k];
        local.push_back(nodes_[deferred[k]]);
        std::vector<uint32_t> localWork{0};
        while (!localWork.empty()) {
          uint32_t n = localWork.back();
          localWork.pop_back();
          Subdivide(local, n, localWork, 1);
        }
      }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < std::min<size_t>(threads, deferred.size()); ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    // Stitch: local node j >= 1 goes to offset + j; local node 0 replaces its root.
    for (size_t k = 0; k < deferred.size(); ++k) {
      std::vector<BuildNode>& local = subtrees[k];
      const uint32_t offset = uint32_t(nodes_.size()) - 1;
      for (BuildNode& n : local)
        if (!n.leaf) n.child[0] += offset, n.child[1] += offset;
      nodes_[deferred[k]] = local[0];
      nodes_.insert(nodes_.end(), local.begin() + 1, local.end());
    }
    return Flatten();
  }

 private:
  static std::vector<float>& RightCostScratch(uint32_t bins) {
    static thread_local std::vector<float> v;
    v.resize(bins);
    return v;
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

  // Splits node ni of `nodes` (or makes it a leaf), appending its children to `nodes`
  // and `work`. Large nodes are binned on `threads` threads.
  void Subdivide(std::vector<BuildNode>& nodes, uint32_t ni, std::vector<uint32_t>& work, unsigned threads) {
    BuildNode node = nodes[ni];
    if (node.count < kParallelNode) threads = 1;
    Bounds3f centroids;
    // The node's box and its centroids' bounds, as two bins (lane by lane min/max).
    auto scan = [&](uint32_t b, uint32_t e, Bin& box, Bin& cent) {
      for (uint32_t i = b; i < e; ++i) {
        const BuildPrim& p = prims_[i];
        Float4 c = Load4(&p.centroid.x);
        box.Extend(Load4(&p.box.lo.x), Load4(&p.box.hi.x));
        cent.Extend(c, c);
      }
    };
    if (threads == 1) {
      Bin box, cent;
      scan(node.first, node.first + node.count, box, cent);
      node.box = box.Box();
      centroids = cent.Box();
    } else {
      // Accumulated locally, merged after: neighbouring vector elements share a cache line.
      std::vector<Bin> boxes(threads), cents(threads);
      ForChunks(node.first, node.count, threads, [&](uint32_t b, uint32_t e, unsigned t) {
        Bin box, cent;
        scan(b, e, box, cent);
        boxes[t] = box;
        cents[t] = cent;
      });
      for (unsigned t = 0; t < threads; ++t) {
        node.box.Extend(boxes[t].Box());
        centroids.Extend(cents[t].Box());
      }
    }
    nodes[ni].box = node.box;
    auto makeLeaf = [&] { nodes[ni].leaf = true; };
    if (node.count == 1) return makeLeaf();

    Split best = FindSplit(node, centroids, threads);
    const float leafCost = opt_.intersectionCost * float(node.count);
    if (node.count <= opt_.maxLeafSize && !(best.cost < leafCost)) return makeLeaf();

    uint32_t mid = node.first;
    if (best.axis >= 0) {
      const int a = best.axis;
      const float lo = centroids.lo[a];
      const float scale = float(opt_.bins) / (centroids.hi[a] - lo);
      auto it = std::partition(prims_.begin() + node.first, prims_.begin() + node.first + node.count,
                               [&](const BuildPrim& p) { return BinOf(p.centroid[a], lo, scale) < best.bin; });
      mid = uint32_t(it - prims_.begin());
    }
    if (mid == node.first || mid == node.first + node.count) {
      // No usable plane (all centroids coincide, or there are only a few primitives
      // too large for a leaf): split at the median along the widest centroid axis, which
      // always makes progress and keeps leaves within maxLeafSize.
      glm::vec3 d = centroids.Diagonal();
      int a = d.x >= d.y && d.x >= d.z ? 0 : (d.y >= d.z ? 1 : 2);
      mid = node.first + node.count / 2;
      std::nth_element(prims_.begin() + node.first, prims_.begin() + mid, prims_.begin() + node.first + node.count,
                       [&](const BuildPrim& p, const BuildPrim& q) { return p.centroid[a] < q.centroid[a]; });
    }
    uint32_t left = uint32_t(nodes.size());
    BuildNode l, r;
    l.first = node.first;
    l.count = mid - node.first;
    r.first = mid;
    r.count = node.first + node.count - mid;
    l.depth = r.depth = node.depth + 1;
    nodes.push_back(l);
    nodes.push_back(r);
    nodes[ni].child[0] = left;
    nodes[ni].child[1] = left + 1;
    work.push_back(left + 1);
    work.push_back(left);
  }

  uint32_t BinOf(float c, float lo, float scale) const {
    return std::min(opt_.bins - 1, uint32_t(std::max(0.0f, (c - lo) * scale)));
  }

  Split FindSplit(const BuildNode& node, const Bounds3f& centroids, unsigned threads) const {
    Split best;
    const float parentArea = node.box.SurfaceArea();
    const uint32_t nb = opt_.bins;
    float scale[3];
    bool usable[3];
    for (int a = 0; a < 3; ++a) {
      const float extent = centroids.hi[a] - centroids.lo[a];
      usable[a] = extent > 0.0f;
      scale[a] = usable[a] ? float(nb) / extent : 0.0f;
    }
    const Float4 lo4{centroids.lo.x, centroids.lo.y, centroids.lo.z, 0.0f};
    const Float4 scale4{scale[0], scale[1], scale[2], 0.0f};
    const Int4 last4 = Int4{1, 1, 1, 1} * int32_t(nb - 1);
    // One pass over the primitives bins all three axes (bins [a·nb, (a+1)·nb)). Each
    // thread fills its own scratch bins, reused across calls (no allocation per node);
    // merging min/max and counts is exact, so the result does not depend on `threads`.
    // The three axes' bin indices come from one vector expression, the same float
    // operations as BinOf (so partitioning agrees with binning); an unusable axis has
    // scale 0 and lands in bin 0, which the sweep below never reads.
    auto binRange = [&](uint32_t b, uint32_t e, std::vector<Bin>& out) {
      out.assign(3 * nb, Bin{});
      for (uint32_t i = b; i < e; ++i) {
        const BuildPrim& p = prims_[i];
        Int4 k = __builtin_convertvector(Max4((Load4(&p.centroid.x) - lo4) * scale4, Splat4(0.0f)), Int4);
        k = k < last4 ? k : last4;
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
    std::vector<float>& rightCost = RightCostScratch(nb);
    for (int a = 0; a < 3; ++a) {
      if (!usable[a]) continue;
      const Bin* bins = all->data() + a * nb;
      // Sweep from the right to get the cost of every right side, then from the left.
      // (Small nodes make most of the calls, so this runs on vectors too.)
      Bin acc;
      for (uint32_t b = opt_.bins - 1; b > 0; --b) {
        acc.Extend(bins[b].lo, bins[b].hi);
        acc.count += bins[b].count;
        rightCost[b] = acc.count ? acc.Area() * float(acc.count) : 0.0f;
      }
      acc = Bin{};
      for (uint32_t b = 1; b < opt_.bins; ++b) {
        acc.Extend(bins[b - 1].lo, bins[b - 1].hi);
        acc.count += bins[b - 1].count;
        if (acc.count == 0 || acc.count == node.count) continue;
        float cost = opt_.traversalCost +
                     opt_.intersectionCost * (acc.Area() * float(acc.count) + rightCost[b]) / parentArea;
        if (cost < best.cost) best = {a, b, cost};
      }
    }
    // A flat parent (zero area) makes every cost NaN or ∞: fall back to the median split.
    if (!(parentArea > 0.0f)) best.axis = -1, best.cost = std::numeric_limits<float>::infinity();
    return best;
  }

  Bvh Flatten() const {
    // Subtree sizes, bottom-up: children always come after their parent in nodes_.
    std::vector<uint32_t> size(nodes_.size(), 1);
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
    return bvh;
  }

  // Writes copy `octant` of the tree at nodes[octant * count ...], depth first, each
  // inner node's children ordered near-first for rays whose direction signs are the
  // octant's (bit 0: x < 0, bit 1: y < 0, bit 2: z < 0). Skip links are absolute.
  void FlattenCopy(const std::vector<uint32_t>& size, uint32_t octant, Bvh& bvh) const {
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
  std::vector<BuildPrim> prims_;
  std::vector<BuildNode> nodes_;
};

}  // namespace

Bvh BuildBvh(std::span<const Bounds3f> primBounds, const BvhBuildOptions& options) {
  if (primBounds.empty()) throw Error("cannot build a BVH over zero primitives");
  if (options.maxLeafSize < 1 || options.maxLeafSize > shader::kMaxLeafSize)
    throw Error("BVH leaf size must be in [1, " + std::to_string(shader::kMaxLeafSize) + "]");
  if (options.bins < 2 || options.bins > 256) throw Error("BVH bin count must be in [2, 256]");
  if (primBounds.size() >= (1u << 28)) throw Error("too many triangles for the BVH layout (limit 2^28)");
  auto t0 = std::chrono::steady_clock::now();
  Bvh bvh = Builder(primBounds, options).Build();
  bvh.stats.buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return bvh;
}

}  // namespace vkpt

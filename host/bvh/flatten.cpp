// Lays out a BuildTree for the renderers (TreeLayout): subtree sizes and statistics by one
// walk, then, when asked, the depth-first skip-link layout (see bvh.h). Every step runs
// on all threads and gives the same bytes for any count.
#include <algorithm>
#include <utility>
#include <vector>

#include "bvh/build_tree.h"
#include "util/parallel.h"

namespace vkpt::internal {
namespace {

class Flattener {
 public:
  Flattener(const BuildTree& tree, const BvhBuildOptions& o, unsigned threads)
      : nodes_(tree.nodes), prims_(tree.prims), rootArea_(tree.rootArea), opt_(o), threads_(threads) {}

  // One walk over the tree: its statistics, and `info` for Write.
  void Measure(FlatInfo& info, BvhStats& st) const {
    const unsigned threads = Threads();
    // Subtrees below kWalkSplit primitives (under a larger parent) are walked first, on
    // all threads, then the top of the tree. The cut does not depend on the thread
    // count, so neither does the order in which the cost is summed: it is the same to
    // the last bit.
    constexpr uint32_t kWalkSplit = 4096;
    std::vector<std::pair<uint32_t, uint32_t>> cut;  // (node, index into cutStats)
    for (std::vector<uint32_t> stack{0}; !stack.empty();) {
      const uint32_t i = stack.back();
      stack.pop_back();
      const BuildNode& n = nodes_[i];
      if (i != 0 && n.count < kWalkSplit) cut.push_back({i, uint32_t(cut.size())});
      else if (!n.IsLeaf()) stack.insert(stack.end(), {n.child + 1, n.child});
    }
    info.size.resize(nodes_.size());
    info.near.resize(nodes_.size());
    std::vector<WalkStats> cutStats(cut.size());
    ParallelFor(cut.size(), threads, [&](size_t k) {
      cutStats[k] = Walk(cut[k].first, info, [](uint32_t) -> const WalkStats* { return nullptr; });
    });
    std::sort(cut.begin(), cut.end());
    const WalkStats top = Walk(0, info, [&](uint32_t node) -> const WalkStats* {
      auto it = std::lower_bound(cut.begin(), cut.end(), std::make_pair(node, 0u));
      return it != cut.end() && it->first == node ? &cutStats[it->second] : nullptr;
    });
    st.nodes = info.size[0];
    st.references = uint32_t(prims_.size());
    st.leaves = top.leaves;
    st.maxLeafPrims = top.maxLeafPrims;
    st.depth = top.depth;
    st.sahCost = top.sahCost;
  }

  // The layout of a measured tree.
  Bvh Write(const FlatInfo& info, const BvhStats& stats) const {
    const unsigned threads = Threads();
    const uint32_t count = stats.nodes;
    Bvh bvh;
    bvh.stats = stats;
    // Partitioning kept every subtree's primitives contiguous in prims_, so a leaf's
    // range [first, first + count) is valid in every child order.
    bvh.primOrder.resize(prims_.size());
    ForChunks(0, uint32_t(prims_.size()), threads, [&](uint32_t b, uint32_t e, unsigned) {
      for (uint32_t i = b; i < e; ++i) bvh.primOrder[i] = prims_[i].index;
    });
    bvh.copies = Copies(opt_, count);
    bvh.nodes.resize(count);
    // The top levels are written here; below `spillBelow` nodes, subtrees are set aside
    // and written by all threads (they fill disjoint ranges of bvh.nodes).
    const uint32_t spillBelow = threads > 1 ? std::max(4096u, count / (16 * threads)) : 0u;
    std::vector<FlatItem> spilled;
    FlattenSubtree(info, {0, 0, shader::kInvalidIndex}, spillBelow, spilled, bvh);
    ParallelFor(spilled.size(), threads, [&](size_t k) {
      std::vector<FlatItem> none;
      FlattenSubtree(info, spilled[k], 0, none, bvh);
    });
    return bvh;
  }

  static uint32_t Copies(const BvhBuildOptions& o, uint32_t nodes) {
    return o.directionCopies && uint64_t(nodes) * sizeof(shader::BvhNode) * 8 <= o.maxCopiesBytes ? 8 : 1;
  }

 private:
  unsigned Threads() const { return nodes_[0].count < 16384 ? 1u : threads_; }

  // What a walk over a subtree finds; depth counts edges from the subtree's root.
  struct WalkStats {
    double sahCost = 0.0;
    uint32_t leaves = 0, maxLeafPrims = 0, depth = 0;
  };

  // One post-order walk of the subtree at `root` (nodes_ has unused gaps, so only a walk
  // finds the nodes): FlatInfo and the statistics, summed in this fixed order. A node
  // other than `root` for which walked(node) gives statistics was walked before: its
  // FlatInfo is set, its statistics are added as they are.
  template <class Walked>
  WalkStats Walk(uint32_t root, FlatInfo& info, Walked&& walked) const {
    HugeVector<uint32_t>& size = info.size;
    WalkStats st;
    struct Visit {
      uint32_t node, depth;
      bool childrenDone;
    };
    std::vector<Visit> walk{{root, 0, false}};
    while (!walk.empty()) {
      const Visit v = walk.back();
      walk.pop_back();
      const BuildNode& n = nodes_[v.node];
      if (v.childrenDone) {
        size[v.node] = 1 + size[n.child] + size[n.child + 1];
        continue;
      }
      if (const WalkStats* w = v.node != root ? walked(v.node) : nullptr) {
        st.sahCost += w->sahCost;
        st.leaves += w->leaves;
        st.maxLeafPrims = std::max(st.maxLeafPrims, w->maxLeafPrims);
        st.depth = std::max(st.depth, v.depth + w->depth);
        continue;
      }
      // Relative area; a flat scene (root area 0) counts every node as 1.
      const double rel = rootArea_ > 0.0f ? double(n.box.SurfaceArea()) / rootArea_ : 1.0;
      st.depth = std::max(st.depth, v.depth);
      if (n.IsLeaf()) {
        size[v.node] = 1;
        ++st.leaves;
        st.maxLeafPrims = std::max(st.maxLeafPrims, n.count);
        st.sahCost += rel * opt_.intersectionCost * n.count;
        continue;
      }
      st.sahCost += rel * opt_.traversalCost;
      const glm::vec3 d = nodes_[n.child + 1].box.Center() - nodes_[n.child].box.Center();
      const glm::vec3 ad = glm::abs(d);
      const int axis = ad.x >= ad.y && ad.x >= ad.z ? 0 : (ad.y >= ad.z ? 1 : 2);
      info.near[v.node] = uint8_t(axis | (d[axis] < 0.0f ? 4 : 0));
      walk.push_back({v.node, v.depth, true});
      walk.push_back({n.child + 1, v.depth + 1, false});
      walk.push_back({n.child, v.depth + 1, false});
    }
    return st;
  }

  // A subtree to write: build node `node` goes to bvh.nodes[flat] with skip link `skip`.
  struct FlatItem {
    uint32_t node, flat, skip;
  };

  // Writes the subtree of `item` depth first, each inner node's children ordered
  // near-first for rays with positive direction components. Subtrees of fewer than
  // `spillBelow` nodes (below the item itself) go to `spilled` instead, to be written
  // later.
  void FlattenSubtree(const FlatInfo& info, FlatItem item, uint32_t spillBelow, std::vector<FlatItem>& spilled,
                      Bvh& bvh) const {
    const HugeVector<uint32_t>& size = info.size;
    std::vector<FlatItem> stack{item};
    while (!stack.empty()) {
      FlatItem it = stack.back();
      stack.pop_back();
      const BuildNode& n = nodes_[it.node];
      shader::BvhNode& out = bvh.nodes[it.flat];
      out.lo = n.box.lo;
      out.hi = n.box.hi;
      out.skip = it.skip;
      if (n.IsLeaf()) {
        out.leaf = (n.first << 4) | n.count;
        continue;
      }
      out.leaf = 0;
      // Near child first along the axis where the children's centres differ most.
      uint32_t first = n.child, second = n.child + 1;
      const uint32_t near = info.near[it.node];
      if ((near >> 2) & 1u) std::swap(first, second);
      const uint32_t secondFlat = it.flat + 1 + size[first];
      for (const FlatItem& child : {FlatItem{second, secondFlat, it.skip}, FlatItem{first, it.flat + 1, secondFlat}})
        (size[child.node] < spillBelow ? spilled : stack).push_back(child);
    }
  }

  const HugeVector<BuildNode>& nodes_;
  const HugeVector<BuildPrim>& prims_;
  float rootArea_;
  const BvhBuildOptions& opt_;
  unsigned threads_;
};

}  // namespace

TreeLayout::TreeLayout(BuildTree tree, const BvhBuildOptions& options, unsigned threads)
    : tree_(std::move(tree)), opt_(options), threads_(threads) {
  Flattener(tree_, opt_, threads_).Measure(info_, stats_);
}

uint32_t TreeLayout::Copies() const { return Flattener::Copies(opt_, stats_.nodes); }

Bvh TreeLayout::Write() const { return Flattener(tree_, opt_, threads_).Write(info_, stats_); }

}  // namespace vkpt::internal

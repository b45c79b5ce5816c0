// The top-down build of a BuildTree: each node is split by the cheapest plane the SAH
// finds (binned object splits, exact ones for small nodes, spatial splits where object
// splits leave overlapping children), or left a leaf when splitting would not pay. The
// nodes are handed out to threads by build_scheduler.h; the builder is iterative, so a
// pathological input cannot overflow the call stack.
#include <algorithm>
#include <vector>

#include "bvh/build_scheduler.h"
#include "bvh/build_tree.h"
#include "bvh/exact_split.h"
#include "bvh/object_split.h"
#include "bvh/partition.h"
#include "bvh/spatial_split.h"
#include "util/parallel.h"

namespace vkpt::internal {
namespace {

// Orders primitives by centroid along `axis`, ties by index (so the order is unique).
struct CentroidLess {
  int axis;
  bool operator()(const BuildPrim& p, const BuildPrim& q) const {
    const float cp = p.Centroid(axis), cq = q.Centroid(axis);
    return cp < cq || (cp == cq && p.index < q.index);
  }
};

// The box of `refs` and their centroids' bounds, extended into box and cent.
void Scan(std::span<const BuildPrim> refs, Bounds3f& box, Bounds3f& cent) {
  Bin boxBin, centBin;  // lane by lane min/max
  for (const BuildPrim& p : refs) {
    const Float4 c = p.Centroid4();
    boxBin.Extend(Load4(&p.box.lo.x), Load4(&p.box.hi.x));
    centBin.Extend(c, c);
  }
  if (!refs.empty()) box.Extend(boxBin.Box()), cent.Extend(centBin.Box());
}

// A child as a split leaves it: its reference count, its box (the union of its
// references' boxes, whichever way the split found it) and its centroid bounds (from the
// pass that put its references in place; small children need none).
struct Child {
  uint32_t count;
  Bounds3f box, centroids;
};

class TreeBuilder {
 public:
  TreeBuilder(std::span<const Bounds3f> bounds, const BvhBuildOptions& o, std::span<const glm::vec3> vertices,
              unsigned threads);
  BuildTree Build();

 private:
  std::span<BuildPrim> Refs(uint32_t first, uint32_t count) { return {prims_.data() + first, count}; }
  void Subdivide(const Task& task, std::vector<Task>& work, unsigned threads);
  SpatialSplit TrySpatialSplit(const Task& task, const BuildNode& node, const Split& best);
  void SplitAtMedian(const Task& task, const BuildNode& node, std::vector<Task>& work);
  void AddScannedChildren(const Task& task, const BuildNode& node, Sides sides, uint32_t slack,
                          std::vector<Task>& work);
  void AddChildren(const Task& task, const BuildNode& node, const Child& l, const Child& r, uint32_t slack,
                   std::vector<Task>& work);
  void CompactReferences();

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

TreeBuilder::TreeBuilder(std::span<const Bounds3f> bounds, const BvhBuildOptions& o,
                         std::span<const glm::vec3> vertices, unsigned threads)
    : opt_(o), verts_(vertices), spatial_(vertices.size() == 3 * bounds.size()), threads_(threads) {
  // The references spatial splits may add; the total stays below 2^28, what a leaf code
  // can address.
  const uint32_t n = uint32_t(bounds.size());
  duplicationBudget_ =
      spatial_ ? uint32_t(std::min<uint64_t>(uint64_t(double(o.maxDuplication) * double(n)), (1u << 28) - 1 - n)) : 0;
  // The primitives, with the root's box and centroid bounds, on all threads; the
  // budget's slots after them stay untouched until used.
  prims_.resize(n + duplicationBudget_);
  std::vector<Bounds3f> boxes(threads_), cents(threads_);
  ForChunks(0, n, threads_, [&](uint32_t b, uint32_t e, unsigned t) {
    for (uint32_t i = b; i < e; ++i) prims_[i].box = bounds[i], prims_[i].index = i;
    Scan(Refs(b, e - b), boxes[t], cents[t]);
  });
  // A tree over m references has at most 2m - 1 nodes.
  nodes_.resize(2 * (n + duplicationBudget_) - 1);
  BuildNode& root = nodes_[0];
  root = {{}, 0, n, 0};
  for (unsigned t = 0; t < threads_; ++t) {
    root.box.Extend(boxes[t]);
    rootCentroids_.Extend(cents[t]);
  }
  rootArea_ = root.box.SurfaceArea();
}

BuildTree TreeBuilder::Build() {
  BuildSubtrees(threads_, {0, 1, duplicationBudget_, nodes_[0].count, rootCentroids_},
                [this](const Task& task, std::vector<Task>& work, unsigned threads) {
                  Subdivide(task, work, threads);
                });
  if (spatial_) CompactReferences();
  return {std::move(nodes_), std::move(prims_), rootArea_};
}

// Splits the node of `task` (or leaves it a leaf): its children go to the start of its
// range, and onto `work`, right then left. The node's box, primitive range and child (0)
// are set; large nodes are binned on `threads` threads.
void TreeBuilder::Subdivide(const Task& task, std::vector<Task>& work, unsigned threads) {
  const BuildNode node = nodes_[task.node];
  if (node.count == 1) return;
  const std::span<BuildPrim> refs = Refs(node.first, node.count);
  const bool exact = node.count <= kExactSplitMax;
  ExactSplit exactSplit;
  if (exact) exactSplit = FindExactSplit(refs, node.box, opt_);
  const Split best = exact ? exactSplit.split : FindObjectSplit(refs, node.box, task.centroids, opt_, threads);
  const SpatialSplit spatial = TrySpatialSplit(task, node, best);
  const float leafCost = opt_.intersectionCost * float(node.count);
  if (node.count <= opt_.maxLeafSize && !(std::min(best.cost, spatial.cost) < leafCost)) return;
  if (spatial.cost < best.cost) {
    const std::optional<Sides> sides =
        SplitSpatially(Refs(node.first, node.count + task.slack), node.count, node.box, spatial, verts_, opt_);
    if (sides) {
      const uint32_t used = sides->left + sides->right - node.count;  // a free slot per reference split in two
      return AddScannedChildren(task, node, *sides, task.slack - used, work);
    }
  }
  if (best.axis < 0) return SplitAtMedian(task, node, work);
  if (exact) {
    ApplyExactSplit(refs, exactSplit);
    const Child l{best.bin, best.left, {}}, r{node.count - best.bin, best.right, {}};
    return AddChildren(task, node, l, r, task.slack, work);
  }
  const Partition p = PartitionByBin(refs, BinMap(task.centroids, opt_.bins), best, threads);
  AddChildren(task, node, {p.leftCount, best.left, p.leftCentroids},
              {node.count - p.leftCount, best.right, p.rightCentroids}, task.slack, work);
}

// Spatial splits are tried where the object split leaves overlapping children (or found
// no plane at all), while the node has slots for more references.
SpatialSplit TreeBuilder::TrySpatialSplit(const Task& task, const BuildNode& node, const Split& best) {
  if (!spatial_ || task.slack == 0) return {};
  const float overlap = best.axis >= 0 ? Intersection(best.left, best.right).SurfaceArea() : node.box.SurfaceArea();
  if (!(overlap > opt_.spatialOverlap * rootArea_)) return {};
  return FindSpatialSplit(Refs(node.first, node.count), node.box, verts_, opt_);
}

// No usable plane (a flat node, or all centroids coincide): split at the median along
// the widest centroid axis, which always makes progress and keeps leaves within
// maxLeafSize.
void TreeBuilder::SplitAtMedian(const Task& task, const BuildNode& node, std::vector<Task>& work) {
  Bounds3f box, cent;
  Scan(Refs(node.first, node.count), box, cent);
  const glm::vec3 d = cent.Diagonal();
  const int a = d.x >= d.y && d.x >= d.z ? 0 : (d.y >= d.z ? 1 : 2);
  const uint32_t mid = node.count / 2;
  std::nth_element(prims_.begin() + node.first, prims_.begin() + node.first + mid,
                   prims_.begin() + node.first + node.count, CentroidLess{a});
  AddScannedChildren(task, node, {mid, node.count - mid}, task.slack, work);
}

// Children whose bounds only a pass over their references can tell.
void TreeBuilder::AddScannedChildren(const Task& task, const BuildNode& node, Sides sides, uint32_t slack,
                                     std::vector<Task>& work) {
  Child l{sides.left, {}, {}}, r{sides.right, {}, {}};
  Scan(Refs(node.first, sides.left), l.box, l.centroids);
  Scan(Refs(node.first + sides.left, sides.right), r.box, r.centroids);
  AddChildren(task, node, l, r, slack, work);
}

// The children's references are at node.first, left then right (l.count + r.count <=
// node.count + slack). `slack` free slots, shared in proportion to the counts, follow
// them: the right ones move up to leave the left child its share.
void TreeBuilder::AddChildren(const Task& task, const BuildNode& node, const Child& l, const Child& r,
                              uint32_t slack, std::vector<Task>& work) {
  const uint32_t leftSlack = uint32_t(uint64_t(slack) * l.count / (l.count + r.count));
  const uint32_t rightFirst = node.first + l.count + leftSlack;
  if (leftSlack > 0)
    std::copy_backward(prims_.begin() + node.first + l.count, prims_.begin() + node.first + l.count + r.count,
                       prims_.begin() + rightFirst + r.count);
  const uint32_t left = task.range;
  nodes_[left] = {l.box, node.first, l.count, 0};
  nodes_[left + 1] = {r.box, rightFirst, r.count, 0};
  nodes_[task.node].child = left;
  work.push_back({left + 1, left + 2 * (l.count + leftSlack), slack - leftSlack, r.count, r.centroids});
  work.push_back({left, left + 2, leftSlack, l.count, l.centroids});
}

// Spatial splits leave unused slots in prims_; this packs the leaves' references in
// depth-first order (so the triangle array follows the tree, as without splits).
void TreeBuilder::CompactReferences() {
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

}  // namespace

BuildTree BuildTreeOver(std::span<const Bounds3f> bounds, const BvhBuildOptions& options,
                        std::span<const glm::vec3> vertices, unsigned threads) {
  return TreeBuilder(bounds, options, vertices, threads).Build();
}

}  // namespace vkpt::internal

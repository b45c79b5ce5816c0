// BuildBvh: checks the input, builds the tree (tree_builder.cpp: binned SAH after Wald
// 2007, with spatial splits after Stich et al. 2009 where asked for) and lays it out
// (flatten.cpp). The tree is the same for any thread count.
#include <chrono>
#include <string>

#include "bvh/build_scheduler.h"
#include "bvh/build_tree.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

void CheckInput(std::span<const Bounds3f> primBounds, const BvhBuildOptions& options,
                std::span<const glm::vec3> vertices) {
  if (primBounds.empty()) throw Error("cannot build a BVH over zero primitives");
  if (options.maxLeafSize < 1 || options.maxLeafSize > shader::kMaxLeafSize)
    throw Error("BVH leaf size must be in [1, " + std::to_string(shader::kMaxLeafSize) + "]");
  if (options.bins < 2 || options.bins > 256) throw Error("BVH bin count must be in [2, 256]");
  if (primBounds.size() >= (1u << 28)) throw Error("too many triangles for the BVH layout (limit 2^28)");
  if (!vertices.empty() && vertices.size() != 3 * primBounds.size())
    throw Error("BVH build: expected three vertices per primitive");
  if (!(options.maxDuplication >= 0.0f)) throw Error("BVH build: the duplication budget must be >= 0");
}

// SplitMode::kAuto keeps the object tree over the spatial one on a tie of SAH costs (as
// fast, with no duplicated references), and whenever the spatial tree is too big for its
// direction-ordered copies while the object tree has them: a fixed traversal order costs
// diffuse rays more box and triangle tests than spatial splits save (see
// docs/design-notes.md).
bool KeepObjectTree(const TreeLayout& object, const TreeLayout& spatial) {
  if (object.Copies() != spatial.Copies()) return object.Copies() > spatial.Copies();
  return object.Stats().sahCost <= spatial.Stats().sahCost;
}

}  // namespace

Bvh BuildBvh(std::span<const Bounds3f> primBounds, const BvhBuildOptions& options,
             std::span<const glm::vec3> vertices) {
  CheckInput(primBounds, options, vertices);
  auto t0 = std::chrono::steady_clock::now();
  const unsigned threads = BuildThreads(uint32_t(primBounds.size()), options.threads);
  auto build = [&](std::span<const glm::vec3> v) {
    return TreeLayout(BuildTreeOver(primBounds, options, v, threads), options, threads);
  };
  const bool spatial = options.splits != SplitMode::kObject && !vertices.empty();
  TreeLayout tree = build(spatial ? vertices : std::span<const glm::vec3>());
  bool keptSpatial = spatial;
  double rejectedSahCost = 0.0;
  if (spatial && options.splits == SplitMode::kAuto) {
    // The trees are compared as measured for their layout (the SAH comes from there);
    // only the one kept is written.
    TreeLayout objectOnly = build({});
    const bool keepObject = KeepObjectTree(objectOnly, tree);
    rejectedSahCost = (keepObject ? tree : objectOnly).Stats().sahCost;
    if (keepObject) tree = std::move(objectOnly), keptSpatial = false;
  }
  Bvh bvh = tree.Write();
  bvh.stats.spatialSplits = keptSpatial;
  bvh.stats.rejectedSahCost = rejectedSahCost;
  bvh.stats.buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return bvh;
}

}  // namespace vkpt::internal

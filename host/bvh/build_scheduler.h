// How the builder spreads a tree over threads: workers take subtrees from a shared list
// and build them depth first on their own. Splitting a node of at least kShareNode
// references while a thread is idle hands its right child to that thread; a node of at
// least kParallelNode references met while every other thread is idle (the root) is
// binned and partitioned on all threads. The tree does not depend on any of this (see
// Task). Internal to host/bvh/.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "util/bounds.h"

namespace vkpt::internal {

constexpr uint32_t kParallelNode = 1u << 15, kShareNode = 1u << 12;

// A node to split, with its centroids' bounds (binning needs them). Its `count`
// references sit at the node's first and may grow, by spatial splits, into the `slack`
// free slots after them; its descendants go to nodes [range, range + 2·(count + slack)
// − 2), the most a subtree over that many references can have: its children first, then
// the left child's range, then the right child's. So every node's place follows from
// the tree alone, whichever thread builds it.
struct Task {
  uint32_t node, range, slack, count;
  Bounds3f centroids;
};

// The threads a build over n references runs on: `requested` (0: all cores), but one
// below kShareNode, where no subtree would ever be handed over.
unsigned BuildThreads(uint32_t n, unsigned requested);

// Splits one node: pushes its children's tasks, if any, onto the vector (right, then
// left), binning on the given number of threads.
using SubdivideFn = std::function<void(const Task&, std::vector<Task>&, unsigned)>;

// Builds the subtree of `root` on `threads` threads by calling `subdivide` for every
// node. An exception from any call stops every thread and is rethrown here.
void BuildSubtrees(unsigned threads, const Task& root, const SubdivideFn& subdivide);

}  // namespace vkpt::internal

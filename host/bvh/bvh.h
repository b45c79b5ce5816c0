// Bounding volume hierarchy over triangles: a binned-SAH builder (bvh_builder.cpp) and the
// flattened depth-first layout with skip links that both renderers traverse (flatten.cpp;
// see shader::BvhNode in shaders/shared/layout.h).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "shared/layout.h"
#include "util/bounds.h"
#include "util/huge_pages.h"

namespace vkpt::internal {

// Which planes may split a node (see BvhBuildOptions::splits).
enum class SplitMode {
  kObject,   // planes between triangles' centroids: every triangle in exactly one leaf
  kSpatial,  // object planes and planes that cut triangles (SBVH)
  kAuto,     // build both trees and keep the one with the lower SAH cost (but never
             // one that lost its direction-ordered copies over one that kept them)
};

// "object", "spatial", "auto" (the command-line names); nullopt for anything else.
inline std::optional<SplitMode> ParseSplitMode(std::string_view name) {
  if (name == "object") return SplitMode::kObject;
  if (name == "spatial") return SplitMode::kSpatial;
  if (name == "auto") return SplitMode::kAuto;
  return std::nullopt;
}

struct BvhBuildOptions {
  uint32_t maxLeafSize = 8;  // 1..shader::kMaxLeafSize
  uint32_t bins = 16;        // SAH candidate planes per axis = bins - 1
  // The SAH's cost of visiting a node, in triangle tests (the surface area heuristic of
  // Goldsmith and Salmon 1987, "Automatic Creation of Object Hierarchies for Ray
  // Tracing", and MacDonald and Booth 1990, "Heuristics for Ray Tracing Using Space
  // Subdivision"). 4, not 1: the tree gets fewer nodes and fuller leaves, and both
  // tracers ran faster so — the CPU tests a leaf's triangles four at a time, so leaves
  // of one or two waste lanes (docs/design-notes.md, "SAH node cost"). SAH costs
  // therefore count a node visit as 4 triangle tests.
  float traversalCost = 4.0f;
  float intersectionCost = 1.0f;
  // Eight copies of the GPU's wide tree (bvh/quantized_layout.h), one per ray-direction
  // octant, each node's children near first for its octant, so that the shader's walk
  // enters near subtrees first (fewer boxes behind an early hit). Only while eight
  // copies of the flattened tree would fit maxCopiesBytes (the wide copies take about
  // half that: 64-byte nodes, about four times fewer; the flattened tree's size is known
  // before either layout is made, so SplitMode::kAuto can weigh it); else one copy.
  bool directionCopies = true;
  unsigned threads = 0;  // build threads; 0 = all cores. The tree is the same for any count.
  // Not a device limit (the nodes are a texel buffer, checked against
  // maxTexelBufferElements on upload): on large trees the copies cost build time and
  // memory for little gain (docs/design-notes.md, "Direction-ordered BVH copies").
  uint64_t maxCopiesBytes = uint64_t(128) << 20;
  // Spatial splits (Stich et al. 2009, "Spatial Splits in Bounding Volume Hierarchies"):
  // a node may also be divided by a plane that cuts triangles; each straddling triangle is
  // then referenced from both sides, with the bounds of its part on that side (or kept
  // whole on one side where that costs less). Boxes overlap less where triangles are
  // long and thin (CAD models); the price is duplicated references and a slower build.
  // Needs the triangles' vertices (without them every mode builds object splits).
  // kAuto exists because the split chosen at each node is only locally the cheapest: on
  // most models spatial splits lower the whole tree's SAH, but where a few large
  // triangles enclose everything (a room's walls) the root's spatial split cuts them, and
  // both subtrees carry the pieces, where an object split would have set them apart
  // (docs/design-notes.md, "Spatial splits and --splits auto").
  SplitMode splits = SplitMode::kObject;
  // Spatial splits are tried only where the object split's children overlap by more than
  // this fraction of the root's surface area (the paper's α).
  float spatialOverlap = 1e-5f;
  // Duplicated references allowed, as a fraction of the triangle count. The budget is
  // shared out down the tree in proportion to the subtrees' sizes.
  float maxDuplication = 1.0f;
};

struct BvhStats {
  uint32_t nodes = 0;  // per copy
  uint32_t references = 0;  // triangle references in leaves (> triangles with spatial splits)
  uint32_t leaves = 0;
  uint32_t depth = 0;         // edges on the longest root-to-leaf path
  uint32_t maxLeafPrims = 0;
  double sahCost = 0.0;       // Σ inner SA/SA_root·Ct + Σ leaf SA/SA_root·n·Ci
  bool spatialSplits = false;  // the tree was built with spatial splits allowed
  double rejectedSahCost = 0.0;  // SplitMode::kAuto: the SAH cost of the tree not kept; else 0
  double buildMs = 0.0;
};

struct Bvh {
  // The flattened tree, stats.nodes nodes, depth first with absolute skip links, its root
  // first and each inner node's children near first for directions of octant 0.
  HugeVector<shader::BvhNode> nodes;
  uint32_t copies = 1;              // of the GPU's wide tree: 8 or 1 (BvhBuildOptions::directionCopies)
  std::vector<uint32_t> primOrder;  // leaf ranges index this: position → input primitive
                                    // (with spatial splits a primitive may appear more than once)
  BvhStats stats;
};

// Builds over primitive bounding boxes (one per triangle). Degenerate boxes (zero area,
// zero extent) are fine. `vertices` holds three per primitive, in order; spatial splits
// need them (and are skipped without them). Throws Error for an empty input or bad
// options.
Bvh BuildBvh(std::span<const Bounds3f> primBounds, const BvhBuildOptions& options = {},
             std::span<const glm::vec3> vertices = {});

// Children of inner node `i` in the flattened layout: the first child is the next node,
// and the second is where the first child's subtree ends, i.e. the first child's skip.
inline uint32_t FirstChild(uint32_t i) { return i + 1; }
inline uint32_t SecondChild(std::span<const shader::BvhNode> nodes, uint32_t i) {
  return nodes[i + 1].skip;
}
inline bool IsLeaf(const shader::BvhNode& n) { return n.leaf != 0u; }
inline uint32_t LeafFirst(const shader::BvhNode& n) { return n.leaf >> 4; }
inline uint32_t LeafCount(const shader::BvhNode& n) { return n.leaf & 15u; }

}  // namespace vkpt::internal

// Spatial splits (Stich et al. 2009, "Spatial Splits in Bounding Volume Hierarchies"):
// planes that may cut triangles, each straddling triangle then referenced from both
// sides with the bounds of its part there, compete with object splits where those leave
// overlapping children. Internal to host/bvh/.
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "bvh/build_tree.h"
#include "bvh/sah.h"

namespace vkpt::internal {

// The plane at the lower boundary of spatial bin `bin` along `axis` (o.bins bins of
// equal width spanning the node's box).
struct SpatialSplit {
  int axis = -1;
  uint32_t bin = 0;
  float cost = std::numeric_limits<float>::infinity();
  Bin left, right;  // the children's boxes and reference counts, every straddler split
};

// The cheapest spatial split of a node with box `box` and references `refs`; `vertices`
// holds three per primitive (BuildPrim::index). None (cost ∞) for a flat node.
SpatialSplit FindSpatialSplit(std::span<const BuildPrim> refs, const Bounds3f& box,
                              std::span<const glm::vec3> vertices, const BvhBuildOptions& o);

struct Sides {
  uint32_t left, right;  // references on each side
};

// Performs `split` on the node whose `count` references start `slots`: the left ones,
// then the right ones, are written from slots[0] on. A straddling reference is split in
// two clipped halves, using one of the free slots after the references, or kept whole on
// one side where that costs less (§4.3), and always once those slots are used up.
// nullopt, with the references untouched, if one side would be empty.
std::optional<Sides> SplitSpatially(std::span<BuildPrim> slots, uint32_t count, const Bounds3f& box,
                                    const SpatialSplit& split, std::span<const glm::vec3> vertices,
                                    const BvhBuildOptions& o);

}  // namespace vkpt::internal

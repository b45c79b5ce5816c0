// Closest-hit and any-hit queries for the CPU reference tracer: an ordered, stack-based
// walk of the flattened BVH (nearer child first, farther one pushed), independent of the
// skip-link walk the shader uses, so one traversal bug cannot hide in both renderers.
#pragma once

#include <cstdint>
#include <vector>

#include "shared/layout.h"

namespace vkpt {

// The hit record the GPU returns too (shaders/shared/layout.h): t < 0 means no hit.
using Hit = shader::HitRecord;

// Per-query counters, for benchmarks and tests.
struct TraversalCounters {
  uint64_t nodesVisited = 0;
  uint64_t trianglesTested = 0;
};

Hit IntersectClosest(const std::vector<shader::BvhNode>& nodes,
                     const std::vector<shader::Triangle>& triangles, glm::vec3 origin, glm::vec3 dir,
                     float tMax, TraversalCounters* counters = nullptr);

// True if anything is hit with t in (0, tMax). `dir` need not be unit length.
bool Occluded(const std::vector<shader::BvhNode>& nodes, const std::vector<shader::Triangle>& triangles,
              glm::vec3 origin, glm::vec3 dir, float tMax);

}  // namespace vkpt

// Closest-hit and any-hit queries for the CPU reference tracer: an ordered, stack-based
// walk of the flattened BVH (nearer child first, farther one pushed), independent of the
// skip-link walk the shader uses, so one traversal bug cannot hide in both renderers.
#pragma once

#include <cstdint>
#include <vector>

#include "shared/layout.h"

namespace vkpt {

struct Hit {
  float t = -1.0f;  // < 0: no hit
  float b1 = 0.0f, b2 = 0.0f;
  uint32_t triangle = shader::kInvalidIndex;  // leaf-order index
  bool Valid() const { return t >= 0.0f; }
};

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

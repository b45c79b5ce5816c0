// The light tree of shared/light_tree.h: a binary tree over the finite lights, built top
// down by the surface area orientation heuristic (Conty Estevez and Kulla 2018, §4.4, as
// pbrt-v4's BVHLightSampler builds it).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "shared/layout.h"

namespace vkpt::internal {

// How light sampling chooses among the finite lights (emissive triangles, point and spot
// lights): by power alone, or through the light tree (shared/light_tree.h) by their
// importance at the shading point; Auto takes the tree from kLightTreeMinLights of them on.
enum class LightSampler { kAuto, kPower, kTree };
constexpr uint32_t kLightTreeMinLights = 8;

// What one light, or a node's lights together, may emit: where (a box), how strongly
// (the sum of the lights' greatest radiant intensities, in luminance) and which way (a
// cone of emission directions: normals within θo of `axis`, emitting up to θe beyond).
struct LightBounds {
  glm::dvec3 lo{0.0}, hi{0.0};
  double intensity = 0.0;
  glm::dvec3 axis{0.0, 0.0, 1.0};
  double cosThetaO = 1.0;
  double cosThetaE = 0.0;
  bool twoSided = false;  // emits along −direction as much as along +direction
};

// The smallest bounds holding both (the cone union of pbrt-v4's DirectionCone::Union).
LightBounds Union(const LightBounds& a, const LightBounds& b);

struct LightTree {
  std::vector<uint32_t> order;               // the lights in leaf order: order[k] is the input's index
  std::vector<shader::LightTreeNode> nodes;  // 2n − 1, depth first (shared/layout.h)
  uint32_t depth = 0;                        // descents from the root to the deepest leaf
};

// The tree over `lights` (at least one), deterministic for a given input. Nodes deeper
// than kLightTreeMaxSahDepth split at the median instead, so that the depth stays below
// kLightTreeMaxSahDepth + log2(n) whatever the lights' layout.
constexpr uint32_t kLightTreeMaxSahDepth = 32;
LightTree BuildLightTree(const std::vector<LightBounds>& lights);

// The node as the shaders read it: a sphere around the box, the cone's angles widened by
// a margin above float rounding: every rounding makes the bound larger, never smaller.
shader::LightTreeNode PackLightNode(const LightBounds& b, uint32_t split);

}  // namespace vkpt::internal

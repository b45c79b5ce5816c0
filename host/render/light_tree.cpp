#include "render/light_tree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace vkpt::internal {
namespace {

constexpr double kPi = 3.14159265358979323846;

double SafeAcos(double x) { return std::acos(std::clamp(x, -1.0, 1.0)); }

double SurfaceArea(const LightBounds& b) {
  glm::dvec3 d = b.hi - b.lo;
  return 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
}

glm::dvec3 Centroid(const LightBounds& b) { return 0.5 * (b.lo + b.hi); }

// The solid angle the node's lights may emit into, weighted by the cosine falloff
// beyond θo (Conty Estevez and Kulla 2018, eq. 1; pbrt-v4's EvaluateCost).
double OrientationMeasure(const LightBounds& b) {
  double thetaO = SafeAcos(b.cosThetaO), thetaE = SafeAcos(b.cosThetaE);
  double thetaW = std::min(thetaO + thetaE, kPi);
  double sinO = std::sqrt(std::max(0.0, 1.0 - b.cosThetaO * b.cosThetaO));
  return 2.0 * kPi * (1.0 - b.cosThetaO) +
         kPi / 2.0 * (2.0 * thetaW * sinO - std::cos(thetaO - 2.0 * thetaW) - 2.0 * thetaO * sinO + b.cosThetaO);
}

// The surface area orientation heuristic of a child with bounds b, split along `axis` of
// a node whose box has extents `extent`: thin nodes split across their long side.
double SplitCost(const LightBounds& b, glm::dvec3 extent, int axis) {
  double longest = std::max({extent.x, extent.y, extent.z});
  return b.intensity * OrientationMeasure(b) * (longest / extent[axis]) * SurfaceArea(b);
}

struct Builder {
  const std::vector<LightBounds>& lights;
  LightTree tree;

  // Builds the subtree over tree.order[first, end) at tree.nodes[at...]; `depth` below
  // the root.
  LightBounds Build(uint32_t first, uint32_t end, uint32_t depth) {
    tree.depth = std::max(tree.depth, depth);
    const size_t at = tree.nodes.size();
    tree.nodes.emplace_back();
    if (end - first == 1) {
      const LightBounds& b = lights[tree.order[first]];
      tree.nodes[at] = PackLightNode(b, 0);
      return b;
    }
    uint32_t split = Partition(first, end, depth);
    LightBounds left = Build(first, split, depth + 1);
    LightBounds right = Build(split, end, depth + 1);
    LightBounds both = Union(left, right);
    tree.nodes[at] = PackLightNode(both, split);
    return both;
  }

  // Orders tree.order[first, end) into two non-empty parts and returns where the second
  // starts: the best of 12 buckets per axis by the heuristic, or the median of the
  // centroids along their longest extent where no bucket split exists (all centroids in
  // one place) or the node is deep.
  uint32_t Partition(uint32_t first, uint32_t end, uint32_t depth) {
    constexpr int kBuckets = 12;
    auto begin = tree.order.begin();
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    LightBounds all = lights[tree.order[first]];
    for (uint32_t i = first; i < end; ++i) {
      glm::dvec3 c = Centroid(lights[tree.order[i]]);
      lo = glm::min(lo, c);
      hi = glm::max(hi, c);
      if (i > first) all = Union(all, lights[tree.order[i]]);
    }
    glm::dvec3 centroidExtent = hi - lo;
    glm::dvec3 extent = glm::max(all.hi - all.lo, glm::dvec3(1e-30));
    auto bucketOf = [&](uint32_t light, int axis) {
      double t = (Centroid(lights[light])[axis] - lo[axis]) / centroidExtent[axis];
      return std::clamp(int(t * kBuckets), 0, kBuckets - 1);
    };
    double bestCost = std::numeric_limits<double>::infinity();
    int bestAxis = -1, bestBucket = 0;
    for (int axis = 0; axis < 3 && depth < kLightTreeMaxSahDepth; ++axis) {
      if (!(centroidExtent[axis] > 0.0)) continue;
      std::array<std::optional<LightBounds>, kBuckets> buckets;
      for (uint32_t i = first; i < end; ++i) {
        std::optional<LightBounds>& bucket = buckets[bucketOf(tree.order[i], axis)];
        const LightBounds& b = lights[tree.order[i]];
        bucket = bucket ? Union(*bucket, b) : b;
      }
      for (int k = 1; k < kBuckets; ++k) {  // buckets [0, k) against [k, kBuckets)
        std::optional<LightBounds> below, above;
        for (int j = 0; j < kBuckets; ++j) {
          if (!buckets[j]) continue;
          std::optional<LightBounds>& side = j < k ? below : above;
          side = side ? Union(*side, *buckets[j]) : *buckets[j];
        }
        if (!below || !above) continue;
        double cost = SplitCost(*below, extent, axis) + SplitCost(*above, extent, axis);
        if (cost < bestCost) {
          bestCost = cost;
          bestAxis = axis;
          bestBucket = k;
        }
      }
    }
    if (bestAxis >= 0) {
      auto mid = std::stable_partition(begin + first, begin + end,
                                       [&](uint32_t l) { return bucketOf(l, bestAxis) < bestBucket; });
      return uint32_t(mid - begin);
    }
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (centroidExtent[a] > centroidExtent[axis]) axis = a;
    const uint32_t mid = first + (end - first) / 2;
    std::stable_sort(begin + first, begin + end, [&](uint32_t a, uint32_t b) {
      double ca = Centroid(lights[a])[axis], cb = Centroid(lights[b])[axis];
      return ca < cb || (ca == cb && a < b);
    });
    return mid;
  }
};

// The largest float ≤ x, and the smallest float ≥ x.
float FloatAtMost(double x) {
  float f = float(x);
  return double(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

float FloatAtLeast(double x) {
  float f = float(x);
  return double(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

}  // namespace

LightBounds Union(const LightBounds& a, const LightBounds& b) {
  LightBounds u;
  u.lo = glm::min(a.lo, b.lo);
  u.hi = glm::max(a.hi, b.hi);
  u.intensity = a.intensity + b.intensity;
  u.twoSided = a.twoSided || b.twoSided;
  u.cosThetaE = std::min(a.cosThetaE, b.cosThetaE);
  // The cone holding both cones: one if it holds the other, else the cone through both
  // cones' far edges, its axis turned from a's towards b's.
  double thetaA = SafeAcos(a.cosThetaO), thetaB = SafeAcos(b.cosThetaO);
  double thetaD = SafeAcos(glm::dot(a.axis, b.axis));
  if (std::min(thetaD + thetaB, kPi) <= thetaA) {
    u.axis = a.axis;
    u.cosThetaO = a.cosThetaO;
    return u;
  }
  if (std::min(thetaD + thetaA, kPi) <= thetaB) {
    u.axis = b.axis;
    u.cosThetaO = b.cosThetaO;
    return u;
  }
  double thetaO = 0.5 * (thetaA + thetaD + thetaB);
  glm::dvec3 turn = glm::cross(a.axis, b.axis);
  if (thetaO >= kPi || glm::dot(turn, turn) == 0.0) {
    u.axis = glm::dvec3(0.0, 0.0, 1.0);
    u.cosThetaO = -1.0;
    return u;
  }
  // Rodrigues' rotation of a.axis about `turn` (perpendicular to it) by θo − θa.
  double thetaR = thetaO - thetaA;
  glm::dvec3 k = glm::normalize(turn);
  u.axis = glm::normalize(a.axis * std::cos(thetaR) + glm::cross(k, a.axis) * std::sin(thetaR));
  u.cosThetaO = std::cos(thetaO);
  return u;
}

shader::LightTreeNode PackLightNode(const LightBounds& b, uint32_t split) {
  // Angles grow by a margin far above float rounding (~1e-7 rad of the axis, and the
  // shader's arithmetic), so that the stored bound holds the exact one.
  constexpr double kMargin = 1e-5;
  shader::LightTreeNode n{};
  glm::dvec3 center = Centroid(b);
  n.center = glm::vec3(center);
  // The sphere around the box, grown by the centre's rounding.
  n.radius = FloatAtLeast(0.5 * glm::length(b.hi - b.lo) + glm::length(glm::dvec3(n.center) - center));
  n.axis = glm::vec3(glm::normalize(b.axis));
  n.intensity = float(b.intensity);
  const double thetaO = std::min(kPi, SafeAcos(b.cosThetaO) + kMargin);
  if (thetaO >= kPi) {
    n.cosThetaO = -1.0f;
    n.sinThetaO = 0.0f;
  } else {  // the float pair of an angle at least θo
    n.cosThetaO = FloatAtMost(std::cos(thetaO));
    n.sinThetaO = thetaO <= kPi / 2 ? FloatAtLeast(std::sin(thetaO)) : FloatAtMost(std::sin(thetaO));
  }
  n.cosThetaE = FloatAtMost(std::cos(std::min(kPi, SafeAcos(b.cosThetaE) + kMargin)));
  n.split = split | (b.twoSided ? shader::kLightNodeTwoSided : 0u);
  return n;
}

LightTree BuildLightTree(const std::vector<LightBounds>& lights) {
  Builder builder{lights, {}};
  builder.tree.order.resize(lights.size());
  for (uint32_t i = 0; i < lights.size(); ++i) builder.tree.order[i] = i;
  builder.tree.nodes.reserve(2 * lights.size());
  if (!lights.empty()) builder.Build(0, uint32_t(lights.size()), 0);
  return std::move(builder.tree);
}

}  // namespace vkpt::internal

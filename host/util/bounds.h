// Axis-aligned bounding box (pbrt's Bounds3f): the value type the BVH builder and the
// loader share.
#pragma once

#include <glm/glm.hpp>
#include <limits>

namespace vkpt::internal {

struct Bounds3f {
  glm::vec3 lo{std::numeric_limits<float>::infinity()};
  glm::vec3 hi{-std::numeric_limits<float>::infinity()};

  bool Empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  void Extend(glm::vec3 p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void Extend(const Bounds3f& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  glm::vec3 Diagonal() const { return hi - lo; }
  glm::vec3 Center() const { return (lo + hi) * 0.5f; }
  // Surface area; 0 for an empty box, so empty bins cost nothing in the SAH.
  float SurfaceArea() const {
    if (Empty()) return 0.0f;
    glm::vec3 d = Diagonal();
    return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
  bool Contains(const Bounds3f& b) const {
    return b.Empty() || (glm::all(glm::lessThanEqual(lo, b.lo)) && glm::all(glm::lessThanEqual(b.hi, hi)));
  }
};

// The box common to a and b (empty if they do not overlap).
inline Bounds3f Intersection(const Bounds3f& a, const Bounds3f& b) {
  return {glm::max(a.lo, b.lo), glm::min(a.hi, b.hi)};
}

}  // namespace vkpt::internal

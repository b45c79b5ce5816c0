// An animation sampler's curve (glTF 2.0 spec §3.11 and Appendix C): keyframe times and
// values, read at any time by STEP, LINEAR (spherical for rotations) or CUBICSPLINE
// (Hermite) interpolation; before the first key and after the last it holds their value.
#pragma once

#include <cstddef>
#include <vector>

namespace vkpt::internal {

enum class Interpolation { kStep, kLinear, kCubicSpline };

struct Keyframes {
  std::vector<double> times;  // seconds, strictly increasing, at least one
  // Per key, `width` components; CUBICSPLINE keeps three such groups a key: in-tangent,
  // value, out-tangent.
  std::vector<double> values;
  size_t width = 0;  // 3 (translation, scale), 4 (rotation quaternion x, y, z, w), or the morph targets' count
  Interpolation mode = Interpolation::kLinear;
  bool rotation = false;  // unit quaternions: LINEAR takes the shorter arc, CUBICSPLINE is renormalized

  // The `width` components at time `t`.
  std::vector<double> At(double t) const;
};

}  // namespace vkpt::internal

#include "gltf/keyframes.h"

#include <algorithm>
#include <cmath>

namespace vkpt::internal {
namespace {

// Spherical linear interpolation of unit quaternions a → b, along the shorter of the
// two arcs between them (q and −q are the same rotation).
std::vector<double> Slerp(const double* a, const double* b, double s) {
  double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  const double sign = d < 0.0 ? -1.0 : 1.0;
  d = std::min(std::abs(d), 1.0);
  double wa = 1.0 - s, wb = s;
  // Near-equal rotations: sin θ → 0, where linear interpolation is the limit.
  if (d < 1.0 - 1e-9) {
    const double theta = std::acos(d), sinTheta = std::sin(theta);
    wa = std::sin((1.0 - s) * theta) / sinTheta;
    wb = std::sin(s * theta) / sinTheta;
  }
  std::vector<double> q(4);
  for (int c = 0; c < 4; ++c) q[c] = wa * a[c] + wb * sign * b[c];
  return q;
}

void Normalize(std::vector<double>& q) {
  const double len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (len > 0.0)
    for (double& c : q) c /= len;
}

}  // namespace

std::vector<double> Keyframes::At(double t) const {
  const size_t keys = times.size();
  const size_t stride = mode == Interpolation::kCubicSpline ? 3 * width : width;
  // The value of key k (for CUBICSPLINE the middle of its three groups).
  auto value = [&](size_t k) { return values.data() + k * stride + (mode == Interpolation::kCubicSpline ? width : 0); };
  auto copy = [&](const double* v) { return std::vector<double>(v, v + width); };
  if (t <= times.front()) return copy(value(0));
  if (t >= times.back()) return copy(value(keys - 1));
  // The interval [t_k, t_k+1) holding t.
  const size_t k = size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
  const double dt = times[k + 1] - times[k], s = (t - times[k]) / dt;
  if (mode == Interpolation::kStep) return copy(value(k));
  if (mode == Interpolation::kLinear) {
    if (rotation) return Slerp(value(k), value(k + 1), s);
    std::vector<double> v(width);
    for (size_t c = 0; c < width; ++c) v[c] = (1.0 - s) * value(k)[c] + s * value(k + 1)[c];
    return v;
  }
  // Cubic Hermite spline between v_k and v_k+1 with key k's out-tangent b_k and key
  // k+1's in-tangent a_k+1, both per second: scaled by the interval's length.
  const double* b = values.data() + k * stride + 2 * width;
  const double* a = values.data() + (k + 1) * stride;
  const double s2 = s * s, s3 = s2 * s;
  std::vector<double> v(width);
  for (size_t c = 0; c < width; ++c)
    v[c] = (2 * s3 - 3 * s2 + 1) * value(k)[c] + dt * (s3 - 2 * s2 + s) * b[c] + (-2 * s3 + 3 * s2) * value(k + 1)[c] +
           dt * (s3 - s2) * a[c];
  if (rotation) Normalize(v);
  return v;
}

}  // namespace vkpt::internal

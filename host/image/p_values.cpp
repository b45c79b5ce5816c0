#include "image/p_values.h"

#include <cmath>
#include <limits>

namespace vkpt::internal {
namespace {

// Continued fraction for the regularized incomplete beta function I_x(a, b), evaluated
// with the modified Lentz method; converges quickly for x < (a + 1) / (a + b + 2).
double BetaContinuedFraction(double a, double b, double x) {
  constexpr double kTiny = 1e-300, kEps = 1e-15;
  auto guard = [](double v) { return std::abs(v) < kTiny ? kTiny : v; };
  double c = 1.0, d = 1.0 / guard(1.0 - (a + b) * x / (a + 1.0)), h = d;
  for (int m = 1; m <= 500; ++m) {
    // Even step: d_{2m} = m(b − m)x / ((a + 2m − 1)(a + 2m)).
    double num = m * (b - m) * x / ((a + 2 * m - 1) * (a + 2 * m));
    d = 1.0 / guard(1.0 + num * d);
    c = guard(1.0 + num / c);
    h *= d * c;
    // Odd step: d_{2m+1} = −(a + m)(a + b + m)x / ((a + 2m)(a + 2m + 1)).
    num = -(a + m) * (a + b + m) * x / ((a + 2 * m) * (a + 2 * m + 1));
    d = 1.0 / guard(1.0 + num * d);
    c = guard(1.0 + num / c);
    double step = d * c;
    h *= step;
    if (std::abs(step - 1.0) < kEps) break;
  }
  return h;
}

double RegularizedIncompleteBeta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x));
  // Use the symmetry I_x(a, b) = 1 − I_{1−x}(b, a) where the fraction converges slowly.
  if (x < (a + 1.0) / (a + b + 2.0)) return front * BetaContinuedFraction(a, b, x) / a;
  return 1.0 - front * BetaContinuedFraction(b, a, 1.0 - x) / b;
}

}  // namespace

double NormalTwoSidedP(double z) { return std::erfc(std::abs(z) / std::sqrt(2.0)); }

// The |z| whose two-sided normal p-value is p (bisection; erfc is monotone). Lets the
// t-test of the fallback report a statistic on the same scale as the Welch z-tests.
double NormalEquivalentZ(double p) {
  if (!(p < 1.0)) return 0.0;
  if (p <= 0.0) return std::numeric_limits<double>::infinity();
  double lo = 0.0, hi = 40.0;  // erfc(40/√2) underflows to 0 in double
  for (int i = 0; i < 100 && hi - lo > 1e-12; ++i) {
    double mid = 0.5 * (lo + hi);
    (NormalTwoSidedP(mid) > p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// P(|T| ≥ t) for Student's t with ν degrees of freedom: I_{ν/(ν+t²)}(ν/2, 1/2).
double StudentTwoSidedP(double t, double nu) {
  if (std::isinf(t)) return 0.0;
  return RegularizedIncompleteBeta(0.5 * nu, 0.5, nu / (nu + t * t));
}

}  // namespace vkpt::internal

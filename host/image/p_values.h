// The two-sided p-values of the region tests of CompareImages (image_compare.h): the
// normal one of the Welch z-tests, Student's t of the paired fallback, and the normal z
// that has a given p-value, so that both report a statistic on the same scale.
#pragma once

namespace vkpt::internal {

// P(|Z| ≥ z) for a standard normal Z.
double NormalTwoSidedP(double z);

// The |z| whose two-sided normal p-value is p: 0 for p ≥ 1, infinity for p ≤ 0.
double NormalEquivalentZ(double p);

// P(|T| ≥ t) for Student's t with ν degrees of freedom (0 for an infinite t).
double StudentTwoSidedP(double t, double nu);

}  // namespace vkpt::internal

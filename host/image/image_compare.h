// Comparing two Monte Carlo renders of the same scene, in two complementary ways:
//
//  * Lockstep: both images came from the same random numbers (e.g. CPU vs GPU with the
//    same seed). Almost every channel agrees to float rounding, but a few diverge wholesale
//    where a branch flips (an edge hit, a roulette threshold, a CDF bin), so the verdict is
//    the *fraction* of channels beyond a tolerance, never the maximum error.
//  * Statistical: the images are independent estimates of the same expectation (different
//    seeds or code paths). Pixels are then compared by region with Welch z-tests on the
//    region means (Welch 1947, "The generalization of 'Student's' problem when several
//    different population variances are involved"), Šidák-corrected over all regions ×
//    channels (Šidák 1967, "Rectangular confidence regions for the means of multivariate
//    normal distributions"), and a significant difference only fails when it is also
//    larger than a small relative margin (so that very long renders do not fail on
//    differences nobody can see).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace vkpt::internal {

struct CompareOptions {
  // Lockstep: a channel differs if |a−b| > relTolerance·max(|a|,|b|) + absFloor. The floor
  // keeps near-black channels (where relative error is meaningless) from counting.
  double relTolerance = 1e-3;
  double absFloor = 1e-6;
  double maxDifferingFraction = 0.01;  // lockstep verdict: at most 1 % of channels differ
  // Statistical: family-wise false-alarm probability over all region × channel tests.
  double alpha = 0.01;
  // A significant region difference smaller than this (relative to the larger region
  // mean) is tolerated.
  double margin = 0.01;
  int regionSize = 16;  // square regions of regionSize × regionSize pixels (edges smaller)
};

struct ChannelStats {
  double meanA = 0, meanB = 0;  // image means over pixels finite in both images
  double meanDiff = 0;          // meanA − meanB
  double ciHalfWidth = 0;       // 95 % confidence half-width of meanDiff (1.96 standard errors)
};

// One region × channel test that was significant (both p < α_Šidák and beyond the margin).
struct RegionResult {
  uint32_t x0 = 0, y0 = 0, width = 0, height = 0;  // pixel rectangle of the region
  int channel = 0;                                 // 0 = R, 1 = G, 2 = B
  double meanA = 0, meanB = 0;
  double z = 0;        // normal-equivalent test statistic (same p-value), signed A − B
  double p = 1;        // two-sided p-value
  double relDiff = 0;  // |meanA − meanB| / max(|meanA|, |meanB|, absFloor)
};

struct ImageComparison {
  uint32_t width = 0, height = 0;

  // Lockstep figures. Channels non-finite in either image count as differing.
  uint64_t channels = 0, differing = 0;
  double differingFraction = 0;
  double maxAbsError = 0;  // over channels finite in both images
  double maxRelError = 0;  // |a−b| / max(|a|, |b|, absFloor), over channels finite in both

  std::array<ChannelStats, 3> perChannel{};

  // Non-finite channel counts (value or, where present, variance). Such channels are left
  // out of every other figure, and any of them makes both verdicts "disagree".
  uint64_t nanA = 0, infA = 0, nanB = 0, infB = 0;

  // Region tests. `usedVariances` says whether the per-pixel variances were used (both
  // images have them) or the paired-difference fallback (see CompareImages).
  bool usedVariances = false;
  int regions = 0;            // regions in the grid
  int tests = 0;              // region × channel tests performed (the Šidák family size)
  double alphaPerTest = 0;    // Šidák per-test α = 1 − (1 − alpha)^(1/tests)
  int significantRegions = 0; // regions with at least one significant channel
  double worstZ = 0;          // largest |z| over all tests (normal-equivalent)
  double worstP = 1;          // smallest p-value over all tests
  std::vector<RegionResult> significant;  // every significant test, in scan order

  bool lockstepAgree = false;       // differingFraction ≤ maxDifferingFraction, all finite
  bool statisticallyAgree = false;  // no significant region, all finite

  CompareOptions options;  // the options used, for Summary()

  // A multi-line human-readable report with every figure above.
  std::string Summary() const;
};

// Compares `a` and `b` (a is conventionally the reference). Throws Error if the sizes
// differ or an image is malformed (pixel/variance count not width × height), or on
// nonsensical options.
//
// Region standard errors: with per-pixel variances of the mean in both images, the region
// mean's squared standard error is Σ var_p / |R|² (pixels are independent estimates), and
// z = (meanA − meanB) / sqrt(seA² + seB²) (Welch; normal because each pixel mean already
// averages many samples). Without variances (e.g. images read from .pfm), the spread of the
// paired pixel differences d_p = a_p − b_p within the region stands in: under the null
// hypothesis every d_p has mean 0 and variance varA_p + varB_p, so s_d² / |R| estimates the
// squared standard error without being inflated by image content (as the spread of the
// pixel values themselves would be). That is a paired t-test with |R| − 1 degrees of
// freedom; its exact p-value is used (small edge regions would be far too optimistic under
// a normal approximation) and regions of a single pixel are skipped.
ImageComparison CompareImages(const Image& a, const Image& b, const CompareOptions& options = {});

// A false-colour picture of where a and b differ, as linear RGB ready for
// WriteImage(..., "x.png"). Per pixel, the largest of the three channel scores is mapped
// black (0) → yellow → red (the top of the scale); pixels non-finite in either image are
// magenta. With variances in both images the score is the z-score |a−b| / sqrt(varA + varB):
// 0 black, 3 yellow, ≥ 6 red (i.e. yellow is "unusual for noise", red "certainly not noise").
// Without, it is the relative error |a−b| / max(|a|, |b|, 1e-6) on a log scale: ≤ 1e-6
// black, 1e-3 yellow, ≥ 1 red. Equal pixels are black in both modes. Throws Error if
// the sizes differ.
Image DifferenceHeatmap(const Image& a, const Image& b);

// The relative MSE of `a` against `reference` (same size): the mean over pixels and
// channels of (a − r)² / (r² + 0.01), vkpt-bench's measure of noise.
double RelativeMse(const Image& a, const Image& reference);

}  // namespace vkpt::internal

#include "image/image_compare.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "image/image_pair.h"
#include "image/p_values.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kZ95 = 1.959963984540054;  // two-sided 95 % normal quantile

void CountNonFinite(const Image& img, size_t i, int c, uint64_t& nan, uint64_t& inf) {
  float v = img.pixels[i][c];
  float var = HasVariance(img) ? img.variance[i][c] : 0.0f;
  if (std::isnan(v) || std::isnan(var))
    ++nan;
  else if (std::isinf(v) || std::isinf(var))
    ++inf;
}

void CheckOptions(const CompareOptions& options) {
  if (options.regionSize <= 0) throw Error("image comparison: regionSize must be positive");
  if (!(options.alpha > 0.0 && options.alpha < 1.0)) throw Error("image comparison: alpha must be in (0, 1)");
  if (!(options.relTolerance >= 0.0 && options.absFloor >= 0.0 && options.margin >= 0.0))
    throw Error("image comparison: tolerances must be non-negative");
}

// Per channel, over the pixels finite in both images: Σa, Σb, Σ(varA + varB), count.
struct ChannelSums {
  std::array<double, 3> sumA{}, sumB{}, sumVar{}, count{};
};

// The lockstep figures and non-finite counts into r; the whole-image channel sums.
ChannelSums LockstepPass(const Image& a, const Image& b, const CompareOptions& options, ImageComparison& r) {
  ChannelSums sums;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      ++r.channels;
      CountNonFinite(a, i, c, r.nanA, r.infA);
      CountNonFinite(b, i, c, r.nanB, r.infB);
      if (!FiniteChannel(a, i, c) || !FiniteChannel(b, i, c)) {
        ++r.differing;
        continue;
      }
      double va = a.pixels[i][c], vb = b.pixels[i][c];
      double diff = std::abs(va - vb), scale = std::max(std::abs(va), std::abs(vb));
      if (diff > options.relTolerance * scale + options.absFloor) ++r.differing;
      r.maxAbsError = std::max(r.maxAbsError, diff);
      r.maxRelError = std::max(r.maxRelError, diff / std::max(scale, options.absFloor));
      sums.sumA[c] += va;
      sums.sumB[c] += vb;
      sums.count[c] += 1;
      if (r.usedVariances) sums.sumVar[c] += double(a.variance[i][c]) + double(b.variance[i][c]);
    }
  r.differingFraction = r.channels ? double(r.differing) / double(r.channels) : 0.0;
  return sums;
}

// Σ (a_p − b_p − meanDiff)² over the pixels of a rectangle finite in both images, for
// channel c: the spread of the paired differences around their mean.
double PairedSquares(const Image& a, const Image& b, int c, double meanDiff, uint32_t x0, uint32_t y0, uint32_t w,
                     uint32_t h) {
  double ss = 0.0;
  for (uint32_t y = y0; y < y0 + h; ++y)
    for (uint32_t x = x0; x < x0 + w; ++x) {
      size_t i = size_t(y) * a.width + x;
      if (!FiniteChannel(a, i, c) || !FiniteChannel(b, i, c)) continue;
      double d = double(a.pixels[i][c]) - double(b.pixels[i][c]) - meanDiff;
      ss += d * d;
    }
  return ss;
}

// Whole-image channel means and the 95 % confidence interval of their difference.
void ChannelStatistics(const Image& a, const Image& b, const ChannelSums& sums, ImageComparison& r) {
  for (int c = 0; c < 3; ++c) {
    ChannelStats& s = r.perChannel[c];
    const double count = sums.count[c];
    if (count == 0) continue;
    s.meanA = sums.sumA[c] / count;
    s.meanB = sums.sumB[c] / count;
    s.meanDiff = s.meanA - s.meanB;
    double se;
    if (r.usedVariances) {
      // The image mean is an average of N independent pixel means: Var = Σ(varA+varB)/N².
      se = std::sqrt(sums.sumVar[c]) / count;
    } else {
      // No variances: the sample variance of the paired differences estimates the average
      // per-pixel varA+varB (plus any real spatially varying difference: conservative).
      double ss = PairedSquares(a, b, c, s.meanDiff, 0, 0, a.width, a.height);
      se = count > 1 ? std::sqrt(ss / (count - 1) / count) : 0.0;
    }
    s.ciHalfWidth = kZ95 * se;
  }
}

// The test of one region × channel (see CompareImages in the header); nothing where the
// region has no pixel finite in both images, or one only and no variances.
std::optional<RegionResult> TestRegion(const Image& a, const Image& b, RegionResult t, bool usedVariances,
                                       double absFloor) {
  const int c = t.channel;
  double sa = 0, sb = 0, sva = 0, svb = 0, m = 0;
  for (uint32_t y = t.y0; y < t.y0 + t.height; ++y)
    for (uint32_t x = t.x0; x < t.x0 + t.width; ++x) {
      size_t i = size_t(y) * a.width + x;
      if (!FiniteChannel(a, i, c) || !FiniteChannel(b, i, c)) continue;
      sa += a.pixels[i][c];
      sb += b.pixels[i][c];
      if (usedVariances) {
        sva += a.variance[i][c];
        svb += b.variance[i][c];
      }
      m += 1;
    }
  if (m == 0 || (!usedVariances && m < 2)) return std::nullopt;
  t.meanA = sa / m;
  t.meanB = sb / m;
  const double diff = t.meanA - t.meanB;
  const double se2 = usedVariances
                         ? (sva + svb) / (m * m)  // seA² + seB², each Σ var_p / |R|²
                         : PairedSquares(a, b, c, diff, t.x0, t.y0, t.width, t.height) / (m - 1) / m;  // s_d² / |R|
  if (se2 <= 0.0) {
    // No noise at all: any difference is certain, none is nothing.
    t.z = diff == 0.0 ? 0.0 : std::copysign(kInf, diff);
    t.p = diff == 0.0 ? 1.0 : 0.0;
  } else if (usedVariances) {
    t.z = diff / std::sqrt(se2);  // Welch z
    t.p = NormalTwoSidedP(t.z);
  } else {
    double tStat = diff / std::sqrt(se2);  // paired t, ν = |R| − 1
    t.p = StudentTwoSidedP(tStat, m - 1);
    t.z = std::copysign(NormalEquivalentZ(t.p), tStat);
  }
  t.relDiff = std::abs(diff) / std::max({std::abs(t.meanA), std::abs(t.meanB), absFloor});
  return t;
}

// Every region × channel test, in scan order, with its region's index; counts r.regions.
std::vector<std::pair<RegionResult, int>> RegionTests(const Image& a, const Image& b, const CompareOptions& options,
                                                      ImageComparison& r) {
  const uint32_t size = uint32_t(options.regionSize);
  std::vector<std::pair<RegionResult, int>> tests;
  for (uint32_t y0 = 0; y0 < a.height; y0 += size)
    for (uint32_t x0 = 0; x0 < a.width; x0 += size) {
      RegionResult region;
      region.x0 = x0, region.y0 = y0, region.width = std::min(size, a.width - x0);
      region.height = std::min(size, a.height - y0);
      for (int c = 0; c < 3; ++c) {
        region.channel = c;
        if (std::optional<RegionResult> t = TestRegion(a, b, region, r.usedVariances, options.absFloor))
          tests.emplace_back(*t, r.regions);
      }
      ++r.regions;
    }
  return tests;
}

// The Šidák-corrected verdict over all tests (Šidák 1967): with m independent tests
// each at α', P(no false alarm) = (1 − α')^m = 1 − alpha. A test fails only when it is
// also beyond the margin: with enough samples every tiny bias becomes significant, and
// only differences that matter should fail.
void ApplySidak(const std::vector<std::pair<RegionResult, int>>& tests, const CompareOptions& options,
                ImageComparison& r) {
  r.tests = int(tests.size());
  r.alphaPerTest = r.tests ? 1.0 - std::pow(1.0 - options.alpha, 1.0 / r.tests) : options.alpha;
  int lastSignificantRegion = -1;
  for (const auto& [t, region] : tests) {
    r.worstZ = std::max(r.worstZ, std::abs(t.z));
    r.worstP = std::min(r.worstP, t.p);
    if (t.p < r.alphaPerTest && t.relDiff > options.margin) {
      r.significant.push_back(t);
      if (region != lastSignificantRegion) ++r.significantRegions;
      lastSignificantRegion = region;
    }
  }
}

}  // namespace

ImageComparison CompareImages(const Image& a, const Image& b, const CompareOptions& options) {
  CheckSameSize(a, b);
  CheckOptions(options);
  ImageComparison r;
  r.options = options;
  r.width = a.width;
  r.height = a.height;
  r.usedVariances = HasVariance(a) && HasVariance(b);

  ChannelSums sums = LockstepPass(a, b, options, r);
  ChannelStatistics(a, b, sums, r);
  // All tests first: the Šidák threshold depends on how many there are (the fallback
  // cannot test single-pixel regions).
  ApplySidak(RegionTests(a, b, options, r), options, r);

  const bool allFinite = r.nanA + r.infA + r.nanB + r.infB == 0;
  r.lockstepAgree = allFinite && r.differingFraction <= options.maxDifferingFraction;
  r.statisticallyAgree = allFinite && r.significantRegions == 0;
  return r;
}

}  // namespace vkpt::internal

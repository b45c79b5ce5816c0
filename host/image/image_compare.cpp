#include "image/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <sstream>
#include <utility>

#include "util/error.h"

namespace vkpt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kZ95 = 1.959963984540054;  // two-sided 95 % normal quantile
constexpr const char* kChannelNames[3] = {"R", "G", "B"};

// P(|Z| ≥ z) for a standard normal Z.
double NormalTwoSidedP(double z) { return std::erfc(std::abs(z) / std::sqrt(2.0)); }

// The |z| whose two-sided normal p-value is p (bisection; erfc is monotone). Lets the
// t-test of the fallback report a statistic on the same scale as the Welch z-tests.
double NormalEquivalentZ(double p) {
  if (!(p < 1.0)) return 0.0;
  if (p <= 0.0) return kInf;
  double lo = 0.0, hi = 40.0;  // erfc(40/√2) underflows to 0 in double
  for (int i = 0; i < 100 && hi - lo > 1e-12; ++i) {
    double mid = 0.5 * (lo + hi);
    (NormalTwoSidedP(mid) > p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

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

// P(|T| ≥ t) for Student's t with ν degrees of freedom: I_{ν/(ν+t²)}(ν/2, 1/2).
double StudentTwoSidedP(double t, double nu) {
  if (std::isinf(t)) return 0.0;
  return RegularizedIncompleteBeta(0.5 * nu, 0.5, nu / (nu + t * t));
}

bool HasVariance(const Image& img) { return !img.variance.empty(); }

void Validate(const Image& img, const char* name) {
  size_t n = size_t(img.width) * img.height;
  if (img.pixels.size() != n)
    throw Error(std::string("image ") + name + ": " + std::to_string(img.pixels.size()) + " pixels for a " +
                std::to_string(img.width) + "×" + std::to_string(img.height) + " image");
  if (HasVariance(img) && img.variance.size() != n)
    throw Error(std::string("image ") + name + ": " + std::to_string(img.variance.size()) + " variances for " +
                std::to_string(n) + " pixels");
}

void CheckSameSize(const Image& a, const Image& b) {
  Validate(a, "A");
  Validate(b, "B");
  if (a.width != b.width || a.height != b.height)
    throw Error("cannot compare images of different sizes: " + std::to_string(a.width) + "×" +
                std::to_string(a.height) + " and " + std::to_string(b.width) + "×" + std::to_string(b.height));
}

// A channel is usable when its value (and variance, if the image has them) is finite.
bool Finite(const Image& img, size_t i, int c) {
  return std::isfinite(img.pixels[i][c]) && (!HasVariance(img) || std::isfinite(img.variance[i][c]));
}

void CountNonFinite(const Image& img, size_t i, int c, uint64_t& nan, uint64_t& inf) {
  float v = img.pixels[i][c];
  float var = HasVariance(img) ? img.variance[i][c] : 0.0f;
  if (std::isnan(v) || std::isnan(var))
    ++nan;
  else if (std::isinf(v) || std::isinf(var))
    ++inf;
}

std::string Fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
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
      if (!Finite(a, i, c) || !Finite(b, i, c)) {
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
      if (!Finite(a, i, c) || !Finite(b, i, c)) continue;
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
      if (!Finite(a, i, c) || !Finite(b, i, c)) continue;
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

std::string ImageComparison::Summary() const {
  const CompareOptions& o = options;
  std::ostringstream s;
  s << "Image comparison, " << width << "×" << height << " (A − B)\n";
  s << "Lockstep: " << differing << " of " << channels << " channels (" << Fmt("%.3f", 100.0 * differingFraction)
    << " %) beyond " << Fmt("%g", o.relTolerance) << " relative + " << Fmt("%g", o.absFloor)
    << " absolute; limit " << Fmt("%g", 100.0 * o.maxDifferingFraction) << " % -> "
    << (lockstepAgree ? "agree" : "DISAGREE") << "\n";
  s << "  max abs error " << Fmt("%.4g", maxAbsError) << ", max rel error " << Fmt("%.4g", maxRelError) << "\n";
  s << "  non-finite channels: A " << nanA << " NaN " << infA << " Inf, B " << nanB << " NaN " << infB << " Inf"
    << (nanA + infA + nanB + infB ? " (forces DISAGREE)" : "") << "\n";
  s << "Channel means, 95 % CI of A − B from "
    << (usedVariances ? "the per-pixel variances" : "the spread of pixel differences (no variances)") << ":\n";
  for (int c = 0; c < 3; ++c) {
    const ChannelStats& p = perChannel[c];
    s << "  " << kChannelNames[c] << ": A " << Fmt("%.6g", p.meanA) << ", B " << Fmt("%.6g", p.meanB) << ", A − B "
      << Fmt("%+.4g", p.meanDiff) << " ± " << Fmt("%.4g", p.ciHalfWidth) << "\n";
  }
  s << "Region tests: " << regions << " regions of " << o.regionSize << "×" << o.regionSize << ", " << tests
    << " tests, standard error from "
    << (usedVariances ? "the per-pixel variances (Welch z)"
                      : "the spread of paired pixel differences within each region (no variances; paired t)")
    << "\n";
  s << "  Šidák α per test " << Fmt("%.3g", alphaPerTest) << " (family " << Fmt("%g", o.alpha) << "), margin "
    << Fmt("%g", 100.0 * o.margin) << " %\n";
  s << "  worst |z| " << Fmt("%.3f", worstZ) << " (p " << Fmt("%.3g", worstP) << "), " << significantRegions
    << " significant region(s) -> " << (statisticallyAgree ? "agree" : "DISAGREE") << "\n";
  const size_t kListed = 10;
  for (size_t k = 0; k < significant.size() && k < kListed; ++k) {
    const RegionResult& t = significant[k];
    s << "    region (" << t.x0 << ", " << t.y0 << ") " << t.width << "×" << t.height << " "
      << kChannelNames[t.channel] << ": A " << Fmt("%.6g", t.meanA) << ", B " << Fmt("%.6g", t.meanB) << ", "
      << Fmt("%.2f", 100.0 * t.relDiff) << " %, z " << Fmt("%+.2f", t.z) << ", p " << Fmt("%.3g", t.p) << "\n";
  }
  if (significant.size() > kListed) s << "    ... and " << significant.size() - kListed << " more\n";
  return s.str();
}

namespace {

// sRGB display value → linear, so the heat map's ramp is even on screen after
// WriteImage's LinearToSrgb8.
float SrgbToLinear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

// t ∈ [0, 1]: black → yellow (0.5) → red (1), in display space.
glm::vec3 HeatColour(double t) {
  t = std::clamp(t, 0.0, 1.0);
  float r = float(std::min(1.0, 2.0 * t)), g = float(t <= 0.5 ? 2.0 * t : 2.0 - 2.0 * t);
  return glm::vec3(SrgbToLinear(r), SrgbToLinear(g), 0.0f);
}

}  // namespace

Image DifferenceHeatmap(const Image& a, const Image& b) {
  CheckSameSize(a, b);
  const bool useVariance = HasVariance(a) && HasVariance(b);
  Image out{a.width, a.height};
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    double score = 0.0;  // in [0, 1], the largest over the channels
    bool finite = true;
    for (int c = 0; c < 3; ++c) {
      if (!Finite(a, i, c) || !Finite(b, i, c)) {
        finite = false;
        break;
      }
      double va = a.pixels[i][c], vb = b.pixels[i][c], d = std::abs(va - vb);
      if (d == 0.0) continue;
      double t;
      if (useVariance) {
        double sd = std::sqrt(double(a.variance[i][c]) + double(b.variance[i][c]));
        t = sd > 0.0 ? d / sd / 6.0 : 1.0;  // z / 6: z = 3 is yellow, z ≥ 6 red
      } else {
        double rel = d / std::max({std::abs(va), std::abs(vb), 1e-6});
        t = (std::log10(rel) + 6.0) / 6.0;  // 1e-6 black, 1e-3 yellow, 1 red
      }
      score = std::max(score, t);
    }
    out.pixels[i] = finite ? HeatColour(score) : glm::vec3(1.0f, 0.0f, 1.0f);
  }
  return out;
}

double RelativeMse(const Image& a, const Image& reference) {
  CheckSameSize(a, reference);
  double total = 0.0;
  for (size_t i = 0; i < reference.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double d = double(a.pixels[i][c]) - reference.pixels[i][c], r = reference.pixels[i][c];
      total += d * d / (r * r + 0.01);
    }
  return total / (3.0 * reference.pixels.size());
}

}  // namespace vkpt

// ImageComparison::Summary: the report `vkpt --diff` prints.
#include "image/image_compare.h"

#include <cstdio>
#include <sstream>

namespace vkpt::internal {
namespace {

constexpr const char* kChannelNames[3] = {"R", "G", "B"};

std::string Fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace

std::string ImageComparison::Summary() const {
  const CompareOptions& o = options;
  std::ostringstream s;
  s << "Image comparison, " << width << "×" << height << " (A − B)\n";
  s << "Lockstep: " << differing << " of " << channels << " channels (" << Fmt("%.3f", 100.0 * differingFraction)
    << " %) beyond " << Fmt("%g", o.relTolerance) << " relative + " << Fmt("%g", o.absFloor) << " absolute; limit "
    << Fmt("%g", 100.0 * o.maxDifferingFraction) << " % -> " << (lockstepAgree ? "agree" : "DISAGREE") << "\n";
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
    s << "    region (" << t.x0 << ", " << t.y0 << ") " << t.width << "×" << t.height << " " << kChannelNames[t.channel]
      << ": A " << Fmt("%.6g", t.meanA) << ", B " << Fmt("%.6g", t.meanB) << ", " << Fmt("%.2f", 100.0 * t.relDiff)
      << " %, z " << Fmt("%+.2f", t.z) << ", p " << Fmt("%.3g", t.p) << "\n";
  }
  if (significant.size() > kListed) s << "    ... and " << significant.size() - kListed << " more\n";
  return s.str();
}

}  // namespace vkpt::internal

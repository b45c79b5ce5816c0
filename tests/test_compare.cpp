// Tests of the image comparison used to judge renders against each other: the lockstep
// fraction-beyond-tolerance verdict, the region z-tests (calibration under the null
// hypothesis and power against a 3 % offset), non-finite handling and the heat map.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "image/image_compare.h"
#include "test_util.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

// A smooth test pattern with different content per channel, all values in [0.1, 1.1].
glm::vec3 TrueMean(uint32_t x, uint32_t y, uint32_t w, uint32_t h) {
  float u = (x + 0.5f) / w, v = (y + 0.5f) / h;
  return glm::vec3(0.1f + u, 0.1f + v, 0.6f + 0.5f * std::sin(6.0f * u + 3.0f * v));
}

Image Pattern(uint32_t w, uint32_t h) {
  Image img{w, h};
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) img.At(x, y) = TrueMean(x, y, w, h);
  return img;
}

// An independent noisy estimate of Pattern: each pixel is its true mean plus normal noise
// with standard deviation relSigma·mean, and the known variance of that pixel mean is
// filled in (as a renderer's Σf² accumulation would estimate it).
Image Noisy(uint32_t w, uint32_t h, double relSigma, uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  Image img = Pattern(w, h);
  img.variance.assign(img.pixels.size(), glm::vec3(0.0f));
  for (size_t i = 0; i < img.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      double sigma = relSigma * img.pixels[i][c];
      img.pixels[i][c] = float(img.pixels[i][c] + sigma * normal(rng));
      img.variance[i][c] = float(sigma * sigma);
    }
  return img;
}

// Scales B's pixels in the rectangle (and their variances, as a brighter render's would be).
void Brighten(Image& img, uint32_t x0, uint32_t y0, uint32_t size, float factor) {
  for (uint32_t y = y0; y < y0 + size; ++y)
    for (uint32_t x = x0; x < x0 + size; ++x) {
      size_t i = size_t(y) * img.width + x;
      img.pixels[i] *= factor;
      if (!img.variance.empty()) img.variance[i] *= factor * factor;
    }
}

TEST(Compare, IdenticalImagesAgree) {
  Image a = Noisy(70, 50, 0.05, 1);  // 70×50: partial regions at the right and bottom edges
  ImageComparison r = CompareImages(a, a);
  std::printf("%s", r.Summary().c_str());
  EXPECT_EQ(r.channels, 70u * 50u * 3u);
  EXPECT_EQ(r.differing, 0u);
  EXPECT_EQ(r.maxAbsError, 0.0);
  EXPECT_EQ(r.maxRelError, 0.0);
  EXPECT_EQ(r.regions, 5 * 4);
  EXPECT_EQ(r.tests, 5 * 4 * 3);
  EXPECT_EQ(r.worstZ, 0.0);
  EXPECT_EQ(r.significantRegions, 0);
  EXPECT_TRUE(r.lockstepAgree);
  EXPECT_TRUE(r.statisticallyAgree);
  for (const ChannelStats& s : r.perChannel) EXPECT_EQ(s.meanDiff, 0.0);
  // Without variances (the paired-difference fallback) identical images still agree.
  a.variance.clear();
  r = CompareImages(a, a);
  EXPECT_FALSE(r.usedVariances);
  EXPECT_EQ(r.differing, 0u);
  EXPECT_TRUE(r.lockstepAgree);
  EXPECT_TRUE(r.statisticallyAgree);
}

// Perturbs `count` channels (spread evenly) of a copy of `a` by 1 %, far beyond the 1e-3
// tolerance, and every other channel by 1e-5 relative (float-rounding-sized, within it).
Image LockstepPartner(const Image& a, uint64_t count) {
  Image b = a;
  const uint64_t channels = b.pixels.size() * 3;
  for (uint64_t k = 0; k < channels; ++k) b.pixels[k / 3][int(k % 3)] *= 1.0f + 1e-5f;
  for (uint64_t j = 0; j < count; ++j) {
    uint64_t k = j * channels / count;
    b.pixels[k / 3][int(k % 3)] *= 1.01f;
  }
  return b;
}

TEST(Compare, LockstepJudgesFractionBeyondTolerance) {
  Image a = Pattern(100, 100);  // 30000 channels
  CompareOptions opt;
  for (auto [count, expectAgree] : {std::pair<uint64_t, bool>{150, true}, {600, false}}) {
    ImageComparison r = CompareImages(a, LockstepPartner(a, count), opt);
    std::printf("%llu perturbed: differing fraction %.4f, limit %.4f (tolerance %g relative + %g) -> %s\n",
                (unsigned long long)count, r.differingFraction, opt.maxDifferingFraction, opt.relTolerance,
                opt.absFloor, r.lockstepAgree ? "agree" : "disagree");
    EXPECT_EQ(r.differing, count);  // the 1e-5 perturbations do not count
    EXPECT_EQ(r.lockstepAgree, expectAgree);
    EXPECT_NEAR(r.maxRelError, 0.01, 2e-4);
  }
}

TEST(Compare, NonFiniteValuesDisagreeAndAreCounted) {
  Image a = Pattern(32, 32);
  Image b = a;
  b.At(3, 4).g = std::numeric_limits<float>::quiet_NaN();
  a.At(10, 20).b = std::numeric_limits<float>::infinity();
  ImageComparison r = CompareImages(a, b);
  std::printf("%s", r.Summary().c_str());
  EXPECT_EQ(r.nanA, 0u);
  EXPECT_EQ(r.infA, 1u);
  EXPECT_EQ(r.nanB, 1u);
  EXPECT_EQ(r.infB, 0u);
  EXPECT_EQ(r.differing, 2u);  // 2 of 3072 channels: under the 1 % limit, yet
  EXPECT_FALSE(r.lockstepAgree);
  EXPECT_FALSE(r.statisticallyAgree);
  EXPECT_TRUE(std::isfinite(r.maxAbsError));
  EXPECT_TRUE(std::isfinite(r.perChannel[1].meanB));  // non-finite channels are left out
  // A NaN variance is as broken as a NaN value.
  Image c = Noisy(32, 32, 0.05, 3), d = c;
  d.variance[5].r = std::nanf("");
  r = CompareImages(c, d);
  EXPECT_EQ(r.nanB, 1u);
  EXPECT_FALSE(r.statisticallyAgree);
}

TEST(Compare, IndependentNoisyImagesAgree) {
  for (bool variances : {true, false}) {
    Image a = Noisy(128, 128, 0.05, 11), b = Noisy(128, 128, 0.05, 12);
    if (!variances) a.variance.clear(), b.variance.clear();
    ImageComparison r = CompareImages(a, b);
    std::printf("%s", r.Summary().c_str());
    std::printf("smallest p %.3g vs Šidák threshold %.3g (%d tests)\n", r.worstP, r.alphaPerTest, r.tests);
    EXPECT_EQ(r.usedVariances, variances);
    EXPECT_EQ(r.tests, 64 * 3);
    EXPECT_GT(r.worstP, r.alphaPerTest);
    EXPECT_EQ(r.significantRegions, 0);
    EXPECT_TRUE(r.statisticallyAgree);
    EXPECT_FALSE(r.lockstepAgree);  // independent noise is not lockstep
    for (const ChannelStats& s : r.perChannel) EXPECT_LT(std::abs(s.meanDiff), 2.0 * s.ciHalfWidth);  // ~4σ
  }
}

// Under the null hypothesis the family-wise false-alarm rate must be about alpha: with a
// standard error off by a factor 2 it would be ~0 or ~1. 200 trials at family α = 0.2:
// Binomial(200, 0.2) has mean 40, sd 5.7. 66×66 has 2-pixel-wide edge regions (paired t
// with 1 and 3 degrees of freedom in the fallback, where a normal approximation fails).
TEST(Compare, FalseAlarmRateMatchesAlpha) {
  CompareOptions opt;
  opt.alpha = 0.2;
  opt.margin = 0.0;
  for (bool variances : {true, false}) {
    int alarms = 0;
    const int trials = 200;
    for (int t = 0; t < trials; ++t) {
      Image a = Noisy(66, 66, 0.05, 1000 + 2 * t), b = Noisy(66, 66, 0.05, 1001 + 2 * t);
      if (!variances) a.variance.clear(), b.variance.clear();
      alarms += !CompareImages(a, b, opt).statisticallyAgree;
    }
    double p = test::ChiSquareSurvival(std::pow(alarms - 0.2 * trials, 2) / (trials * 0.2 * 0.8), 1);
    std::printf("%s: %d false alarms in %d trials at family α %.2f (expected %.0f), binomial p %.3g vs 0.001\n",
                variances ? "variances" : "fallback", alarms, trials, opt.alpha, 0.2 * trials, p);
    EXPECT_GT(p, 0.001);
  }
}

TEST(Compare, OffsetRegionIsSignificant) {
  const uint32_t x0 = 32, y0 = 48, size = 32;  // exactly 2×2 regions of 16×16
  for (bool variances : {true, false}) {
    Image a = Noisy(128, 128, 0.05, 21), b = Noisy(128, 128, 0.05, 22);
    Brighten(b, x0, y0, size, 1.03f);
    if (!variances) a.variance.clear(), b.variance.clear();
    ImageComparison r = CompareImages(a, b);
    std::printf("%s", r.Summary().c_str());
    std::printf("worst |z| %.2f, p %.3g vs Šidák threshold %.3g; margin %.2f\n", r.worstZ, r.worstP, r.alphaPerTest,
                r.options.margin);
    EXPECT_EQ(r.significantRegions, 4);
    EXPECT_FALSE(r.statisticallyAgree);
    for (const RegionResult& t : r.significant) {
      EXPECT_TRUE(t.x0 >= x0 && t.x0 < x0 + size && t.y0 >= y0 && t.y0 < y0 + size) << t.x0 << ", " << t.y0;
      EXPECT_LT(t.z, 0.0);  // B is brighter
      EXPECT_NEAR(t.relDiff, 0.03, 0.015);
    }
    // A margin above the offset tolerates it, however significant.
    CompareOptions lenient;
    lenient.margin = 0.05;
    r = CompareImages(a, b, lenient);
    std::printf("margin %.2f: worst |z| %.2f, %d significant regions\n", lenient.margin, r.worstZ,
                r.significantRegions);
    EXPECT_GT(r.worstZ, 5.0);
    EXPECT_TRUE(r.statisticallyAgree);
  }
}

TEST(Compare, SizeMismatchThrows) {
  Image a{16, 16}, b{16, 17};
  EXPECT_THROW(CompareImages(a, b), Error);
  EXPECT_THROW(DifferenceHeatmap(a, b), Error);
  Image c{16, 16};
  c.variance.resize(3);  // malformed: variance count ≠ pixel count
  EXPECT_THROW(CompareImages(a, c), Error);
  try {
    CompareImages(a, b);
  } catch (const Error& e) {
    std::printf("error: %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("16×17"), std::string::npos);
  }
}

TEST(Compare, HeatmapIsBlackWhereEqual) {
  for (bool variances : {true, false}) {
    Image a = Noisy(40, 30, 0.05, 31), b = a;
    if (!variances) a.variance.clear(), b.variance.clear();
    b.At(5, 6).r *= 1.5f;  // far beyond noise (z ≈ 7) and beyond 1e-3 relative
    b.At(7, 8).g = std::nanf("");
    b.At(9, 10).b *= 1.0f + 1e-4f;  // z ≈ 0.002 / 1e-7 relative: near-black in both modes
    Image h = DifferenceHeatmap(a, b);
    ASSERT_EQ(h.width, 40u);
    ASSERT_EQ(h.height, 30u);
    ASSERT_EQ(h.pixels.size(), 40u * 30u);
    EXPECT_TRUE(h.variance.empty());
    for (uint32_t y = 0; y < 30; ++y)
      for (uint32_t x = 0; x < 40; ++x) {
        if ((x == 5 && y == 6) || (x == 7 && y == 8) || (x == 9 && y == 10)) continue;
        ASSERT_EQ(h.At(x, y), glm::vec3(0.0f)) << x << ", " << y;
      }
    glm::vec3 hot = h.At(5, 6), nan = h.At(7, 8), faint = h.At(9, 10);
    std::printf("%s: differing pixel (%.3f %.3f %.3f), NaN pixel (%.3f %.3f %.3f), 1e-4 pixel (%.3f %.3f %.3f)\n",
                variances ? "z-score" : "relative", hot.r, hot.g, hot.b, nan.r, nan.g, nan.b, faint.r, faint.g,
                faint.b);
    EXPECT_GT(hot.r, 0.9f);  // red end of the scale
    EXPECT_EQ(nan, glm::vec3(1.0f, 0.0f, 1.0f));
    EXPECT_LT(faint.r, hot.r);
    EXPECT_GT(faint.r + faint.g, 0.0f);  // a difference is never shown as pure black
  }
}

}  // namespace
}  // namespace vkpt::internal

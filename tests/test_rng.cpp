// The counter-based RNG: range, uniformity, independence of streams, determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <unordered_set>

#include "shared/rng.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

using shader::Random4;
using shader::ToUnitFloat;

TEST(Rng, UnitFloatRangeIsHalfOpen) {
  EXPECT_EQ(ToUnitFloat(0u), 0.0f);
  EXPECT_LT(ToUnitFloat(0xFFFFFFFFu), 1.0f);
  EXPECT_EQ(ToUnitFloat(0xFFFFFFFFu), 1.0f - 1.0f / 16777216.0f);
  EXPECT_EQ(ToUnitFloat(0x80000000u), 0.5f);
}

// Fixed outputs: the GPU test kernel must reproduce these bit for bit, and any change to
// the hash (which would silently change every image) fails here first.
TEST(Rng, GoldenValues) {
  glm::uvec4 h = shader::Pcg4d(glm::uvec4(1u, 2u, 3u, 4u));
  std::printf("Pcg4d(1,2,3,4) = %08x %08x %08x %08x\n", h.x, h.y, h.z, h.w);
  EXPECT_EQ(h, glm::uvec4(0x3622cd16u, 0xf11471d8u, 0xe1109b3fu, 0x02b94c2fu));
}

// χ² test of one coordinate stream, over 1M numbers in 1001 bins.
double UniformityPValue(std::function<float(uint32_t)> draw, uint32_t n, int bins, double* stat, int* dof) {
  std::vector<double> observed(bins, 0.0), expected(bins, double(n) / bins);
  for (uint32_t i = 0; i < n; ++i) {
    float x = draw(i);
    EXPECT_TRUE(x >= 0.0f && x < 1.0f);
    observed[std::min(bins - 1, int(x * bins))] += 1.0;
  }
  return test::ChiSquareTest(observed, expected, stat, dof);
}

TEST(Rng, EachDimensionIsUniform) {
  // Family: 4 components × 3 ways of walking the key space = 12 tests.
  const double alpha = test::SidakAlpha(0.01, 12);
  for (int c = 0; c < 4; ++c) {
    std::function<float(uint32_t)> walks[3] = {
        [c](uint32_t i) { return Random4(7u, i, 0u, 0u)[c]; },         // across pixels
        [c](uint32_t i) { return Random4(7u, 123u, i, 5u)[c]; },       // across samples
        [c](uint32_t i) { return Random4(i, 99u, 17u, 2u)[c]; },       // across seeds
    };
    for (int w = 0; w < 3; ++w) {
      double stat;
      int dof;
      double p = UniformityPValue(walks[w], 1000000, 1001, &stat, &dof);
      std::printf("component %d walk %d: chi2 = %.1f, dof = %d, p = %.4f (alpha %.5f)\n", c, w, stat, dof, p, alpha);
      EXPECT_GT(p, alpha);
    }
  }
}

// Two coordinates drawn by `draw(i)` for i < 1M, binned on a 31×31 grid: χ² against the
// uniform joint distribution; p must exceed `alpha` for every pair.
struct Pair {
  const char* name;
  std::function<glm::vec2(uint32_t)> draw;
};

void ExpectJointlyUniform(const std::vector<Pair>& pairs, double alpha) {
  const int grid = 31;
  const uint32_t n = 1000000;
  for (const Pair& pr : pairs) {
    std::vector<double> observed(grid * grid, 0.0), expected(grid * grid, double(n) / (grid * grid));
    for (uint32_t i = 0; i < n; ++i) {
      glm::vec2 v = pr.draw(i);
      observed[int(v.x * grid) * grid + int(v.y * grid)] += 1.0;
    }
    double stat;
    int dof;
    double p = test::ChiSquareTest(observed, expected, &stat, &dof);
    std::printf("%s: chi2 = %.1f, dof = %d, p = %.4f (alpha %.5f)\n", pr.name, stat, dof, p, alpha);
    EXPECT_GT(p, alpha) << pr.name;
  }
}

// Pairs drawn from neighbouring streams must be jointly uniform on [0,1)²: a 2-D χ²
// catches correlation between pixels, samples, dimension groups and seeds.
TEST(Rng, NeighbouringStreamsAreIndependent) {
  const double alpha = test::SidakAlpha(0.01, 5);
  std::vector<Pair> pairs = {
      {"pixel i / pixel i+1", [](uint32_t i) { return glm::vec2(Random4(1u, i, 0u, 0u).x, Random4(1u, i + 1, 0u, 0u).x); }},
      {"sample i / sample i+1", [](uint32_t i) { return glm::vec2(Random4(1u, 5u, i, 0u).x, Random4(1u, 5u, i + 1, 0u).x); }},
      {"group g / group g+1", [](uint32_t i) { return glm::vec2(Random4(1u, i, 3u, 1u).y, Random4(1u, i, 3u, 2u).y); }},
      {"seed s / seed s+1", [](uint32_t i) { return glm::vec2(Random4(i, 8u, 3u, 1u).z, Random4(i + 1, 8u, 3u, 1u).z); }},
      {"x / y of one call", [](uint32_t i) { glm::vec4 r = Random4(2u, i, 0u, 0u); return glm::vec2(r.x, r.y); }},
  };
  ExpectJointlyUniform(pairs, alpha);
}

TEST(Rng, DistinctKeysGiveDistinctNumbers) {
  // pcg4d is a bijection of 128-bit keys; 2^20 keys must give 2^20 distinct outputs.
  std::unordered_set<uint64_t> seen;
  for (uint32_t i = 0; i < (1u << 20); ++i) {
    glm::uvec4 h = shader::Pcg4d(glm::uvec4(i & 1023u, i >> 10, 0u, 0u));
    seen.insert((uint64_t(h.x) << 32) | h.y);
  }
  EXPECT_EQ(seen.size(), size_t(1u << 20));
}

TEST(Rng, IsAPureFunctionOfItsKey) {
  for (uint32_t i = 0; i < 1000; ++i) EXPECT_EQ(Random4(3u, i, i * 7u, 2u), Random4(3u, i, i * 7u, 2u));
  EXPECT_NE(Random4(3u, 1u, 2u, 3u), Random4(4u, 1u, 2u, 3u));
}

TEST(Rng, LoopFreeSobolMatchesDirectionNumbers) {
  // Reference: XOR of direction numbers v1 = 2^31, v(k+1) = v(k) ^ (v(k) >> 1).
  std::mt19937 rng(3);
  for (uint32_t n = 0; n < 200000; ++n) {
    uint32_t index = n < 100000 ? n : uint32_t(rng());
    uint32_t ref = 0, v = 1u << 31;
    for (uint32_t i = index; i; i >>= 1, v ^= v >> 1)
      if (i & 1) ref ^= v;
    ASSERT_EQ(shader::SobolSecondDimension(index), ref) << "index " << index;
  }
  EXPECT_EQ(shader::ReverseBits(1u), 0x80000000u);
  EXPECT_EQ(shader::ReverseBits(0x12345678u), 0x1E6A2C48u);
}

// Sample2D leaves out paired bit reversals; its values must be those of the plain
// composition: scrambled index, then each Sobol dimension Owen-scrambled.
TEST(Rng, Sample2DEqualsTheScrambledSobolComposition) {
  std::mt19937 rng(5);
  for (int n = 0; n < 100000; ++n) {
    uint32_t seed = rng(), pixel = rng(), sample = n < 50000 ? uint32_t(n) : uint32_t(rng()), pair = rng() % 64;
    glm::uvec4 h = shader::Pcg4d(glm::uvec4(pixel, pair, seed, 0x50B0150Bu));
    uint32_t index = shader::NestedUniformScramble(sample, h.x);
    uint32_t x = shader::NestedUniformScramble(shader::ReverseBits(index), h.y);
    uint32_t y = shader::NestedUniformScramble(shader::SobolSecondDimension(index), h.z);
    glm::vec2 u = shader::Sample2D(seed, pixel, sample, pair);
    ASSERT_EQ(u.x, shader::ToUnitFloat(x)) << n;
    ASSERT_EQ(u.y, shader::ToUnitFloat(y)) << n;
  }
}

// The first 2^m samples of a pixel's pair form a (0, m, 2)-net: every elementary
// interval [a/2^i, (a+1)/2^i) × [b/2^j, (b+1)/2^j) with i + j = m holds exactly one point.
TEST(Rng, Sample2DIsStratifiedPerPixel) {
  const int m = 8, n = 1 << m;
  int nets = 0;
  for (uint32_t pixel : {0u, 17u, 40000u})
    for (uint32_t pair : {0u, 1u, 6u}) {
      std::vector<glm::vec2> p(n);
      for (int s = 0; s < n; ++s) p[s] = shader::Sample2D(9u, pixel, uint32_t(s), pair);
      for (int i = 0; i <= m; ++i) {
        const int cols = 1 << i, rows = 1 << (m - i);
        std::vector<int> count(n, 0);
        for (const glm::vec2& q : p) ++count[int(q.y * rows) * cols + int(q.x * cols)];
        for (int c : count) ASSERT_EQ(c, 1) << "pixel " << pixel << " pair " << pair << " interval " << cols << "x" << rows;
      }
      ++nets;
    }
  std::printf("%d pixel/pair combinations: all 9 elementary-interval shapes of 256 samples hold one point each\n", nets);
}

// Different pairs, and different pixels, must be independent: a 2-D χ² on coordinates
// taken from two streams at the same sample index.
TEST(Rng, Sample2DPairsAndPixelsAreIndependent) {
  const double alpha = test::SidakAlpha(0.01, 3);
  std::vector<Pair> pairs = {
      {"pair 1 x / pair 2 x, one pixel", [](uint32_t i) { return glm::vec2(shader::Sample2D(1u, 7u, i, 1u).x, shader::Sample2D(1u, 7u, i, 2u).x); }},
      {"pair 0 y / pair 3 x, one pixel", [](uint32_t i) { return glm::vec2(shader::Sample2D(1u, 7u, i, 0u).y, shader::Sample2D(1u, 7u, i, 3u).x); }},
      {"pixel p / pixel p+1, sample 0", [](uint32_t i) { return glm::vec2(shader::Sample2D(1u, i, 0u, 1u).x, shader::Sample2D(1u, i + 1, 0u, 1u).x); }},
  };
  ExpectJointlyUniform(pairs, alpha);
}

}  // namespace
}  // namespace vkpt::internal

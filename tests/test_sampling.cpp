// χ² tests of the sampling routines against their stated densities.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cpu/cpu_path.h"
#include "shared/rng.h"
#include "shared/sampling.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

using namespace shader;

constexpr uint32_t kSamples = 1000000;

// Cosine-weighted hemisphere: bin directions on a (cos θ, φ) grid of odd resolution;
// the expected mass of a cell is ∫∫ (cos θ / π) sin θ dθ dφ = (φ1 − φ0)(z1² − z0²) / (2π).
// Done in a rotated frame, so FrameFromNormal and FrameToWorld are tested too.
TEST(Sampling, CosineHemisphereMatchesItsPdf) {
  const int nz = 21, nphi = 41;
  const double alpha = 0.01;  // one test
  const glm::vec3 n = glm::normalize(glm::vec3(0.3f, -0.8f, 0.52f));
  Frame f = FrameFromNormal(n);
  EXPECT_NEAR(glm::dot(f.t, f.b), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(f.t, f.n), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(f.t), 1.0f, 1e-6f);
  std::vector<double> observed(nz * nphi, 0.0), expected(nz * nphi, 0.0);
  for (uint32_t i = 0; i < kSamples; ++i) {
    glm::vec4 u = Random4(5u, i, 0u, 0u);
    glm::vec3 w = FrameToWorld(f, SampleCosineHemisphere(u.x, u.y));
    ASSERT_NEAR(glm::length(w), 1.0f, 1e-5f);
    // Back to the local frame to bin.
    float z = glm::dot(w, f.n), x = glm::dot(w, f.t), y = glm::dot(w, f.b);
    ASSERT_GE(z, -1e-6f);
    double phi = std::atan2(double(y), double(x));
    if (phi < 0) phi += 2 * M_PI;
    int iz = std::min(nz - 1, int(std::max(0.0f, z) * nz));
    int ip = std::min(nphi - 1, int(phi / (2 * M_PI) * nphi));
    observed[iz * nphi + ip] += 1.0;
  }
  for (int iz = 0; iz < nz; ++iz) {
    double z0 = double(iz) / nz, z1 = double(iz + 1) / nz;
    for (int ip = 0; ip < nphi; ++ip)
      expected[iz * nphi + ip] = kSamples * (2 * M_PI / nphi) * (z1 * z1 - z0 * z0) / (2 * M_PI);
  }
  double stat;
  int dof;
  double p = test::ChiSquareTest(observed, expected, &stat, &dof);
  std::printf("cosine hemisphere: chi2 = %.1f, dof = %d, p = %.4f (alpha %.3f)\n", stat, dof, p, alpha);
  EXPECT_GT(p, alpha);
}

TEST(Sampling, CosinePdfIntegratesToOne) {
  // Midpoint rule over the sphere: ∫ pdf dω = 1 (the lower hemisphere contributes 0).
  const int n = 2000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    double theta = (i + 0.5) * M_PI / n;
    sum += CosineHemispherePdf(float(std::cos(theta))) * std::sin(theta) * (M_PI / n) * 2 * M_PI;
  }
  EXPECT_NEAR(sum, 1.0, 1e-4);
}

// Uniform triangle sampling: barycentrics (b1, b2) binned on a grid over the unit
// square; a cell's expected mass is its area inside the triangle b1 + b2 ≤ 1 over 1/2.
TEST(Sampling, TriangleSamplingIsUniformInArea) {
  const int g = 25;
  std::vector<double> observed(g * g, 0.0), expected(g * g, 0.0);
  for (uint32_t i = 0; i < kSamples; ++i) {
    glm::vec4 u = Random4(9u, i, 1u, 3u);
    glm::vec2 b = SampleUniformTriangle(u.z, u.w);
    ASSERT_TRUE(b.x >= 0.0f && b.y >= 0.0f && b.x + b.y <= 1.0f + 1e-6f);
    observed[std::min(g - 1, int(b.x * g)) * g + std::min(g - 1, int(b.y * g))] += 1.0;
  }
  for (int i = 0; i < g; ++i)
    for (int j = 0; j < g; ++j) {
      double area = i + j + 2 <= g ? 1.0 : (i + j + 1 == g ? 0.5 : 0.0);  // full, diagonal, outside
      expected[i * g + j] = kSamples * area / (g * g) * 2.0;
    }
  // Drop the empty cells (expected 0) so pooling does not merge them into real ones.
  std::vector<double> obs, exp;
  for (size_t k = 0; k < expected.size(); ++k) {
    if (expected[k] == 0.0) {
      EXPECT_EQ(observed[k], 0.0) << "sample outside the triangle";
      continue;
    }
    obs.push_back(observed[k]);
    exp.push_back(expected[k]);
  }
  double stat;
  int dof;
  double p = test::ChiSquareTest(obs, exp, &stat, &dof);
  std::printf("triangle: chi2 = %.1f, dof = %d, p = %.4f (alpha 0.01)\n", stat, dof, p);
  EXPECT_GT(p, 0.01);
}

// Light selection: triangle probabilities ∝ area × luminance (× 2 if two-sided), and the
// table's pmf is exactly what the CDF search realises.
TEST(Sampling, LightSelectionFollowsPower) {
  std::vector<SceneTriangle> tris;
  std::vector<vkpt::internal::Material> mats;
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> u(0.1f, 2.0f);
  for (int i = 0; i < 40; ++i) {
    vkpt::internal::Material m{};
    m.emission = i % 5 == 0 ? glm::vec3(0.0f) : glm::vec3(u(rng), u(rng), u(rng));
    m.doubleSided = i % 3 == 0;
    mats.push_back(m);
    float s = u(rng);
    glm::vec3 o(float(i) * 3.0f, 0.0f, 0.0f);
    tris.push_back({o, o + glm::vec3(s, 0, 0), o + glm::vec3(0, s * 0.7f, 0), uint32_t(i)});
  }
  RenderScene rs = PrepareRenderScene(test::MakeScene(tris, mats));
  ASSERT_EQ(rs.lights.size(), 32u);
  double total = 0.0;
  std::vector<double> power;
  for (const Light& l : rs.lights) {
    const shader::Material& m = rs.materials[rs.triangles[l.triangle].material];
    double w = l.extent * Luminance(m.emission) * ((m.flags & kMaterialDoubleSided) ? 2.0 : 1.0);
    power.push_back(w);
    total += w;
  }
  std::vector<double> observed(rs.lights.size(), 0.0), expected;
  for (size_t k = 0; k < rs.lights.size(); ++k) {
    EXPECT_NEAR(rs.lights[k].pmf, power[k] / total, 1e-6);
    expected.push_back(kSamples * double(rs.lights[k].pmf));
  }
  EXPECT_EQ(rs.lights.back().cdf, 1.0f);
  FrameParams params{};
  params.lightCount = uint32_t(rs.lights.size());
  int misreported = 0;
  for (uint32_t i = 0; i < kSamples; ++i) {
    LightChoice c = ChooseLight(rs, params, vec3(0.0f), vec3(0.0f), Random4(1u, i, 0u, 1u).x);
    observed[c.light] += 1.0;
    misreported += c.pmf != rs.lights[c.light].pmf;
  }
  EXPECT_EQ(misreported, 0);
  double stat;
  int dof;
  double p = test::ChiSquareTest(observed, expected, &stat, &dof);
  std::printf("light choice: chi2 = %.1f, dof = %d, p = %.4f (alpha 0.01)\n", stat, dof, p);
  EXPECT_GT(p, 0.01);
}

}  // namespace
}  // namespace vkpt::internal

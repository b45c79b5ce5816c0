// KHR_materials_sheen's lobe (shared/sheen.h) in the BSDF (shared/bsdf.h): its albedo table
// against an independent quadrature and the published points, D's normalisation, a white
// sheen over a lossless base returning exactly what it receives, the sheen alone
// reflecting its colour times its albedo, and the samplers against their pdfs (χ²), each
// with a mutant the test must reject.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "bsdf_harness.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

using namespace bsdf_test;
using shader::Material;  // the GPU layout the BSDF reads, not the Scene's

Material Sheened(Material m, vec3 color, float roughness) {
  m.sheenColor = color;
  m.sheenRoughness = roughness;
  return m;
}

// The sheen's albedo E(μo) = ∫ D V cos θi dωi with sheenColor 1, by midpoint quadrature
// over (cos θi, φ), written out here from the extension's formulas (Conty Estevez & Kulla
// 2017) apart from the shaders, in double. cos θi is spaced as t² so that the horizon,
// where the lobe lies for small α, is integrated finely.
double SheenQuadrature(double mu, double alpha, int n = 600) {
  auto lambda = [&](double c) {
    const double t = (1.0 - alpha) * (1.0 - alpha);
    const double a = 21.5473 + (25.3245 - 21.5473) * t, b = 3.82987 + (3.32435 - 3.82987) * t;
    const double cc = 0.19823 + (0.16801 - 0.19823) * t, d = -1.97760 + (-1.27393 + 1.97760) * t;
    const double e = -4.32054 + (-4.85967 + 4.32054) * t;
    auto l = [&](double x) { return a / (1.0 + b * std::pow(x, cc)) + d * x + e; };
    return c < 0.5 ? std::exp(l(c)) : std::exp(2.0 * l(0.5) - l(1.0 - c));
  };
  const double so = std::sqrt(1.0 - mu * mu), lo = lambda(mu);
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double t = (i + 0.5) / n, ci = t * t, si = std::sqrt(1.0 - ci * ci);
      const double phi = M_PI * (j + 0.5) / n;  // the lobe is symmetric about ωo's plane
      const double hx = so + si * std::cos(phi), hy = si * std::sin(phi), hz = mu + ci;
      const double cosH = hz / std::sqrt(hx * hx + hy * hy + hz * hz);
      const double d = (2.0 + 1.0 / alpha) * std::pow(1.0 - cosH * cosH, 0.5 / alpha) / (2.0 * M_PI);
      // D V cos θi dωi with dωi = d(cos θi) dφ = 2t dt dφ, over φ ∈ [0, π] twice.
      sum += d / (4.0 * mu * (1.0 + lo + lambda(ci))) * 2.0 * t * 2.0;
    }
  return sum * M_PI / (double(n) * n);
}

// engineering-facts.md's points, by 400 × 400 quadrature: they settle α = sheenRoughness².
struct PublishedPoint {
  float mu, roughness, albedo;
};
const PublishedPoint kPublished[] = {{0.1f, 0.25f, 0.549f}, {0.5f, 0.25f, 0.060f}, {0.5f, 0.5f, 0.188f},
                                     {1.0f, 0.5f, 0.027f},  {0.1f, 1.0f, 0.721f},  {0.5f, 1.0f, 0.356f},
                                     {1.0f, 1.0f, 0.164f}};

TEST(SheenAlbedo, TableMatchesThePublishedPoints) {
  std::printf("sheen albedo at the published points (table, quadrature), within 0.0015:\n");
  for (const PublishedPoint& p : kPublished) {
    const float alpha = SheenAlpha(p.roughness);
    const double table = SheenAlbedo(p.mu, alpha), quadrature = SheenQuadrature(p.mu, alpha);
    std::printf("  mu %.2f r %.2f: published %.3f, table %.4f, quadrature %.4f (alpha = r: %.4f)\n", p.mu, p.roughness,
                p.albedo, table, quadrature, SheenQuadrature(p.mu, p.roughness));
    EXPECT_NEAR(table, p.albedo, 0.0015) << "mu " << p.mu << " r " << p.roughness;
    EXPECT_NEAR(quadrature, p.albedo, 0.0006) << "mu " << p.mu << " r " << p.roughness;
  }
}

// The generator integrated the shaders' own lobe with their own sampler; an independent
// quadrature agrees at the grid points, and the bilinear lookup between them, where the
// lobe is not a spike on the horizon (μ ≥ 0.05, α ≥ 0.01: below, E is the fitted Λ's
// grazing artefact, and the lobe is divided by it anyway). A table computed at α = r
// instead of r² fails the published points above.
TEST(SheenAlbedo, TableMatchesAnIndependentQuadrature) {
  double worstGrid = 0.0, worstMid = 0.0;
  int checked = 0;
  for (uint32_t i = 2; i < kSheenAlbedoCosines; i += 7)
    for (uint32_t j = 0; j < kSheenAlbedoRoughnesses; j += 5) {
      const float s = float(i) / float(kSheenAlbedoCosines - 1u), mu = s * s, alpha = SheenTableAlpha(j);
      if (mu < 0.05f || alpha < 0.01f) continue;
      const double grid = std::abs(SheenAlbedo(mu, alpha) - SheenQuadrature(mu, alpha));
      worstGrid = std::max(worstGrid, grid);
      EXPECT_LT(grid, 5e-4) << "grid point mu " << mu << " alpha " << alpha;
      if (j + 1u < kSheenAlbedoRoughnesses && i + 1u < kSheenAlbedoCosines) {
        const float s1 = (float(i) + 0.5f) / float(kSheenAlbedoCosines - 1u), mu1 = s1 * s1;
        const float alpha1 = std::sqrt(alpha * SheenTableAlpha(j + 1u));  // halfway in log α
        const double mid = std::abs(SheenAlbedo(mu1, alpha1) - SheenQuadrature(mu1, alpha1));
        worstMid = std::max(worstMid, mid);
        EXPECT_LT(mid, 3e-3) << "cell centre mu " << mu1 << " alpha " << alpha1;
      }
      ++checked;
    }
  std::printf(
      "sheen table vs quadrature at %d grid points: worst %.2e (limit 5e-4); at cell centres: worst %.2e "
      "(limit 3e-3)\n",
      checked, worstGrid, worstMid);
  EXPECT_GT(checked, 40);
}

// ∫ D(h) cos θh dωh = 1 for every α.
TEST(SheenAlbedo, DistributionIsNormalised) {
  for (float alpha : {kMinSheenAlpha, 0.01f, 0.1f, 0.5f, 1.0f}) {
    const int n = 20000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      const double c = (i + 0.5) / n;  // cos θh; dωh = d(cos θh) dφ
      sum += SheenD(float(c), alpha) * c * 2.0 * M_PI / n;
    }
    std::printf("  alpha %.3f: integral of D cos = %.6f\n", alpha, sum);
    EXPECT_NEAR(sum, 1.0, 1e-3) << "alpha " << alpha;
  }
}

const float kMus[] = {0.1f, 0.4f, 1.0f};
const float kSheenRoughness[] = {0.1f, 0.4f, 1.0f};

// A white sheen over each lossless base, alone and under a white clear coat, returns 1 at
// every μo and sheen roughness: the sheen reflects min(E(μo), 1), the base the rest.
TEST(SheenFurnace, WhiteSheenOverALosslessBaseReturnsOne) {
  std::printf("white sheen over a lossless base, albedo by SampleBsdf (2e5 stratified samples), 1 +- 0.5%% + 3 se:\n");
  uint32_t seed = 1300;
  double worst = 0.0;
  for (const Base& base : kLosslessBases)
    for (float coat : {0.0f, 1.0f})
      for (float r : kSheenRoughness)
        for (float mu : kMus) {
          Material m = Sheened(base.material, vec3(1.0f), r);
          m.clearcoat = coat;
          m.clearcoatRoughness = 0.3f;
          const Albedo a = EstimateAlbedo(m, mu, seed++, kFurnaceStrata);
          worst = std::max(worst, std::abs(a.mean.y - 1.0));
          std::printf("  %-22s coat %.0f sheen r %.1f mu %.1f: %.4f +- %.4f\n", base.name, coat, r, mu, a.mean.y,
                      a.stderr_.y);
          EXPECT_NEAR(a.mean.y, 1.0, 0.005 + 3.0 * a.stderr_.y) << base.name << " r " << r << " mu " << mu;
        }
  std::printf("  worst deviation from 1: %.4f\n", worst);
}

// A coloured sheen over white Lambert reflects at most what it receives in every channel,
// and exactly that in the channel of max(sheenColor), which scales the base.
TEST(SheenFurnace, ColouredSheenReturnsOneInItsLargestChannel) {
  const vec3 color(1.0f, 0.5f, 0.2f);
  uint32_t seed = 1400;
  for (float r : kSheenRoughness)
    for (float mu : kMus) {
      const Albedo a = EstimateAlbedo(Sheened(kLosslessBases[0].material, color, r), mu, seed++, kFurnaceStrata);
      std::printf("  sheen (1, 0.5, 0.2) r %.1f mu %.1f: (%.4f, %.4f, %.4f)\n", r, mu, a.mean.x, a.mean.y, a.mean.z);
      EXPECT_NEAR(a.mean.x, 1.0, 0.005 + 3.0 * a.stderr_.x);
      EXPECT_LE(a.mean.y, 1.0 + 1e-6 + 3.0 * a.stderr_.y);
      EXPECT_LE(a.mean.z, a.mean.y + 1e-6 + 3.0 * a.stderr_.z);
    }
}

// The furnace has teeth: the base given everything (no albedo scaling) returns more than 1.
TEST(SheenFurnace, CatchesAMissingAlbedoScaling) {
  for (float mu : kMus) {
    const vec3 wo = Outgoing(mu);
    Bsdf b = PrepareBsdf(Sheened(kLosslessBases[0].material, vec3(1.0f), 0.6f), wo, true, kUp);
    b.sheenBaseScale = 1.0f;
    const Albedo a = EstimateAlbedo(b, wo, 1450);
    std::printf("  mutant without albedo scaling, mu %.1f: %.4f +- %.4f (must exceed 1.005 + 3 se)\n", mu, a.mean.y,
                a.stderr_.y);
    EXPECT_GT(a.mean.y, 1.005 + 3.0 * a.stderr_.y) << "mu " << mu;
  }
}

// Over a black base the material reflects only its sheen: sheenColor min(E(μo), 1) with E
// by the independent quadrature, at each (roughness, μo); E at α = r (the other reading
// of the extension) must be rejected by the same tolerance where it differs.
TEST(SheenFurnace, SheenAloneReflectsItsColourTimesItsAlbedo) {
  const Material black = MakeMaterial(vec3(0.0f), 0.0f, 0.5f, 0.0f, 1.5f);
  const vec3 color(0.9f, 0.6f, 0.3f);
  std::printf("sheen over black, albedo vs colour x quadrature, within 0.5%% + 3 se:\n");
  uint32_t seed = 1500;
  for (float r : kSheenRoughness)
    for (float mu : kMus) {
      const Albedo a = EstimateAlbedo(Sheened(black, color, r), mu, seed++);
      const double e = std::min(SheenQuadrature(mu, SheenAlpha(r)), 1.0);
      const double wrong = std::min(SheenQuadrature(mu, std::max(r, kMinSheenAlpha)), 1.0);
      const double expected = color.x * e, tolerance = 0.005 * expected + 3.0 * a.stderr_.x + 1e-5;
      std::printf("  r %.1f mu %.1f: %.5f +- %.5f, expected %.5f (alpha = r: %.5f)\n", r, mu, a.mean.x, a.stderr_.x,
                  expected, color.x * wrong);
      EXPECT_NEAR(a.mean.x, expected, tolerance) << "r " << r << " mu " << mu;
      if (r < 1.0f && expected > 1e-3) {
        EXPECT_GT(std::abs(color.x * wrong - expected), tolerance) << "alpha = r would pass, r " << r;
      }
      EXPECT_NEAR(a.mean.z / a.mean.x, color.z / color.x, 1e-4);
    }
}

constexpr int kSheenChi2Cases = 8;
const double kSheenChi2Alpha = test::SidakAlpha(0.01, kSheenChi2Cases);

// SampleSheen against SheenPdf alone, at α from the floor to 1.
TEST(SheenChi2, LobeSamplerMatchesItsPdf) {
  std::printf("chi2 of SampleSheen against SheenPdf, Sidak alpha %.5f over %d:\n", kSheenChi2Alpha, kSheenChi2Cases);
  uint32_t seed = 1600;
  for (float alpha : {kMinSheenAlpha, 0.01f, 0.25f, 1.0f}) {
    Chi2Result r = RunChi2(
        [&](vec3 u, vec3* wi) {
          *wi = SampleSheen(alpha, u.y, u.z);
          return SheenPdf(*wi, alpha) > 0.0f;
        },
        [&](vec3 wi) { return double(SheenPdf(wi, alpha)); }, seed++);
    PrintChi2("SampleSheen alpha " + std::to_string(alpha), r, kSheenChi2Alpha);
    EXPECT_GT(r.p, kSheenChi2Alpha) << "alpha " << alpha;
    EXPECT_NEAR(r.pdfMass, 1.0 - r.noSample, 5.0 * r.massSigma + 2e-3) << "alpha " << alpha;
  }
}

struct SheenCase {
  const char* name;
  Material material;
  float muO;
};

// A rough coat: a smooth one's spike is beyond the χ² grid's numeric integral of the pdf.
Material Coated(Material m, float coat) {
  m.clearcoat = coat;
  m.clearcoatRoughness = 0.2f;
  return m;
}

const SheenCase kSheenCases[4] = {
    {"sheen r 0.5 over red Lambert, mu_o 0.5",
     Sheened(MakeMaterial(vec3(0.8f, 0.2f, 0.1f), 0.0f, 0.6f, 0.0f, 1.5f), vec3(1.0f), 0.5f), 0.5f},
    {"sheen r 0.2 over dielectric r 0.3, mu_o 0.2",
     Sheened(MakeMaterial(vec3(0.3f, 0.5f, 0.7f), 0.0f, 0.3f, 1.0f, 1.5f), vec3(0.7f, 0.7f, 1.0f), 0.2f), 0.2f},
    {"sheen r 1 over metal r 0.2, mu_o 0.9",
     Sheened(MakeMaterial(vec3(0.9f, 0.6f, 0.3f), 1.0f, 0.2f, 1.0f, 1.5f), vec3(0.5f), 1.0f), 0.9f},
    {"sheen r 0.4 under a coat, over glass, mu_o 0.6",
     Coated(Sheened(Transmissive(MakeMaterial(vec3(0.9f), 0.0f, 0.3f, 1.0f, 1.5f), 0.7f, true), vec3(0.8f), 0.4f),
            1.0f),
     0.6f},
};

// The full mixture with a sheen lobe against BsdfPdf.
TEST(SheenChi2, MixtureMatchesBsdfPdf) {
  uint32_t seed = 1700;
  for (const SheenCase& c : kSheenCases)
    ExpectSamplerMatchesPdf(c.material, c.muO, kUp, &Bsdf::pSheen, c.name, kSheenChi2Alpha, seed++);
}

// The tests have teeth: a sampler exponent 20 % off its pdf's, and a mixture pdf that
// counts the sheen's samples as the cosine lobe's, are both rejected.
TEST(SheenChi2, CatchesWrongPdfs) {
  const float alpha = 0.25f;
  Chi2Result lobe = RunChi2(
      [&](vec3 u, vec3* wi) {
        *wi = SampleSheen(alpha, u.y, u.z);
        return true;
      },
      [&](vec3 wi) { return double(SheenPdf(wi, alpha * 1.2f)); }, 1800);
  PrintChi2("mutant: pdf of exponent 0.1 / (1.2 alpha)", lobe, kSheenChi2Alpha);
  EXPECT_LT(lobe.p, kSheenChi2Alpha);

  ExpectPdfWithoutLobeRejected(kSheenCases[0].material, kSheenCases[0].muO, kUp, &Bsdf::pSheen,
                               "mutant: mixture pdf without the sheen lobe", kSheenChi2Alpha, 1801);
}

// Random sheened (and sometimes coated, transmissive) materials, both faces.
TEST(Sheen, SampleWeightIsFCosOverPdf) {
  ExpectSampleWeightsAreFCosOverPdf("sheened", 23, [](Uniform& u) {
    Material m = MakeMaterial(u.Vec3(), u() < 0.5f ? 0.0f : u(), u(), u() < 0.5f ? 0.0f : 1.0f, 1.0f + 2.0f * u());
    if (u() < 0.3f) m = Transmissive(m, u(), u() < 0.5f);
    if (u() < 0.3f) m.clearcoat = u();
    return std::pair(Sheened(m, u.Vec3(), u() < 0.1f ? 0.0f : u()), kUp);
  });
}

}  // namespace
}  // namespace vkpt::internal

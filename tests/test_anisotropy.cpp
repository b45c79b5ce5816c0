// KHR_materials_anisotropy (shared/microfacet.h, shared/bsdf.h, shared/normal_map.h):
// the anisotropic GGX distribution is normalised and its masking passes the weak white
// furnace over a grid of (αx, αy); strength 0 is the isotropic material bit for bit; a
// rotation of π/2 is the tangent and bitangent swapped; white anisotropic metals and
// glasses keep their energy to what the effective-α compensation leaves (printed); the
// sampler matches its pdf (χ², reflection and transmission) and weights are f cos / pdf.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "bsdf_harness.h"
#include "shared/normal_map.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

using namespace bsdf_test;
using shader::Material;  // the GPU layout the BSDF reads, not the Scene's

Material Anisotropic(Material m, float strength) {
  m.anisotropy = strength;
  m.anisotropyDirection = vec2(1.0f, 0.0f);
  return m;
}

const float kAlphas[] = {0.02f, 0.1f, 0.4f, 1.0f};

// ∫ g(h) dω over the upper hemisphere by the midpoint rule in (u, φ), tan θ = s u / (1 − u)
// with s the smaller α: the lobe's width is resolved whatever α.
template <class G>
double HemisphereIntegral(float s, const G& g) {
  constexpr int kU = 1200, kPhi = 720;
  double sum = 0.0;
  for (int i = 0; i < kU; ++i) {
    const double u = (i + 0.5) / kU, t = s * u / (1.0 - u);
    const double dtdu = s / ((1.0 - u) * (1.0 - u));
    const double cosTheta = 1.0 / std::sqrt(1.0 + t * t), sinTheta = t * cosTheta;
    // dω = sin θ dθ dφ, dθ = dt / (1 + t²) = cos²θ dt.
    const double weight = sinTheta * cosTheta * cosTheta * dtdu / kU * (2.0 * kPi / kPhi);
    for (int j = 0; j < kPhi; ++j) {
      const double phi = (j + 0.5) * 2.0 * kPi / kPhi;
      sum += weight * g(vec3(float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)), float(cosTheta)));
    }
  }
  return sum;
}

// ∫ D(h) cos θh dω = 1, and ∫ G1(ωo) max(0, ωo·h) D(h) dω / cos θo = 1 (Heitz 2014's weak
// white furnace) for ωo at three elevations and two azimuths.
TEST(Anisotropy, DistributionIsNormalisedAndPassesTheWeakFurnace) {
  double worstD = 0.0, worstG = 0.0;
  for (float ax : kAlphas)
    for (float ay : kAlphas) {
      if (ax == ay) continue;
      const vec2 a(ax, ay);
      const float s = std::min(ax, ay);
      worstD = std::max(worstD, std::abs(HemisphereIntegral(s, [&](vec3 h) { return GgxD(h, a) * h.z; }) - 1.0));
      for (float mu : {0.2f, 0.6f, 0.95f})
        for (float phi : {0.3f, 1.2f}) {
          const float sinO = std::sqrt(1.0f - mu * mu);
          const vec3 wo(sinO * std::cos(phi), sinO * std::sin(phi), mu);
          const double g1 = 2.0 * mu / (mu + GgxLambdaRoot(wo, a));
          const double w = HemisphereIntegral(s, [&](vec3 h) { return std::max(0.0f, dot(wo, h)) * GgxD(h, a); });
          worstG = std::max(worstG, std::abs(g1 * w / mu - 1.0));
        }
    }
  std::printf(
      "anisotropic GGX over alpha {0.02, 0.1, 0.4, 1}^2: |int D cos - 1| <= %.2e, weak furnace |. - 1| <= %.2e "
      "(limits 2e-3)\n",
      worstD, worstG);
  EXPECT_LE(worstD, 2e-3);
  EXPECT_LE(worstG, 2e-3);
}

// Strength 0 is the isotropic material: f, pdf and samples bit for bit.
TEST(Anisotropy, StrengthZeroIsTheIsotropicMaterial) {
  ExpectSameBsdf(59, 20000, [](Uniform& u) {
    Material plain = MakeMaterial(u.Vec3(), u() < 0.5f ? 0.0f : u(), u(), u() < 0.2f ? 0.0f : 1.0f, 1.0f + u());
    if (u() < 0.3f) plain = Transmissive(plain, u(), u() < 0.5f);
    Material zero = Anisotropic(plain, 0.0f);
    zero.anisotropyDirection = vec2(0.6f, 0.8f);
    return std::pair(plain, zero);
  });
}

// A rotation of π/2 turns the lobe's x axis onto the bitangent: the frame equals the one
// whose tangent is that bitangent, and the lobe in it is the one with αx and αy swapped.
TEST(Anisotropy, QuarterTurnSwapsTangentAndBitangent) {
  Uniform u(61);
  for (int i = 0; i < 1000; ++i) {
    const vec3 n = u.Hemisphere();
    const Frame base = FrameFromNormal(n);
    const vec3 t = normalize(base.t + 0.3f * (u() - 0.5f) * n);  // not quite orthogonal, as interpolated
    const float sign = u() < 0.5f ? -1.0f : 1.0f;
    const vec3 bitangent = sign * cross(n, t);
    const Frame turned = AnisotropicFrame(base, vec4(t, sign), vec2(std::cos(0.5f * kPi), std::sin(0.5f * kPi)));
    const Frame swapped = AnisotropicFrame(base, vec4(bitangent, 1.0f), vec2(1.0f, 0.0f));
    for (int c = 0; c < 3; ++c) {
      ASSERT_NEAR(turned.t[c], swapped.t[c], 1e-6f) << i;
      ASSERT_NEAR(turned.b[c], swapped.b[c], 1e-6f) << i;
    }
    const vec2 a(0.05f + u(), 0.05f + u());
    const vec3 h = u.Hemisphere();
    ASSERT_NEAR(GgxD(vec3(h.y, -h.x, h.z), a), GgxD(h, vec2(a.y, a.x)), 1e-5f * GgxD(h, vec2(a.y, a.x))) << i;
  }
}

// White anisotropic metals and glass walls, compensated as the isotropic lobe of
// α = sqrt(αx αy): the albedo over azimuths, elevations and strengths (printed for
// docs/limits.md). Bounded: no more than 1 + 3.5 % anywhere (energy is not created), at
// least 0.9 up to strength 0.5 and 0.55 at strength 1, where the lobe is as rough as can
// be along x. Mutant: without the compensation (the tables read at the base's α), the
// mean loss over the grid grows.
TEST(AnisotropyFurnace, WhiteMaterialsKeepTheirEnergyToTheCompensationsLimits) {
  std::printf("white anisotropic materials, albedo (limits: <= 1.035, >= 0.9 at strength 0.5, >= 0.55 at 1):\n");
  uint32_t seed = 2700;
  double lowest = 2.0, highest = 0.0, meanLoss = 0.0, mutantMeanLoss = 0.0;
  int cases = 0;
  for (float roughness : {0.2f, 0.5f})
    for (float strength : {0.5f, 1.0f})
      for (float mu : {0.2f, 0.7f})
        for (float phi : {0.0f, 0.25f * kPi, 0.5f * kPi})
          for (int kind = 0; kind < 2; ++kind) {
            const float sinO = std::sqrt(1.0f - mu * mu);
            const vec3 wo(sinO * std::cos(phi), sinO * std::sin(phi), mu);
            Material m = kind == 0 ? MakeMaterial(vec3(1.0f), 1.0f, roughness, 1.0f, 1.5f)
                                   : Transmissive(MakeMaterial(vec3(1.0f), 0.0f, roughness, 1.0f, 1.5f), 1.0f, false);
            m = Anisotropic(m, strength);
            Bsdf b = PrepareBsdf(m, wo, true, kUp);
            const Albedo a = EstimateAlbedo(b, wo, seed++, kFurnaceStrata / 4);
            std::printf("  %-9s r %.1f s %.1f mu %.1f phi %.2f: %.4f +- %.4f\n", kind == 0 ? "metal" : "thin wall",
                        roughness, strength, mu, phi, a.mean.y, a.stderr_.y);
            lowest = std::min(lowest, a.mean.y);
            highest = std::max(highest, a.mean.y);
            EXPECT_LE(a.mean.y, 1.035 + 3.0 * a.stderr_.y);
            EXPECT_GE(a.mean.y, (strength <= 0.5f ? 0.9 : 0.55) - 3.0 * a.stderr_.y);
            meanLoss += std::abs(1.0 - a.mean.y);
            // The mutant: the lobe compensated as its base's isotropic lobe.
            const Bsdf base = PrepareBsdf(Anisotropic(m, 0.0f), wo, true, kUp);
            b.albedoO = base.albedoO, b.invMsNorm = base.invMsNorm, b.msWeight = base.msWeight;
            b.glassScale = base.glassScale;
            b.alpha = base.alpha;
            mutantMeanLoss += std::abs(1.0 - EstimateAlbedo(b, wo, seed++, kFurnaceStrata / 4).mean.y);
            ++cases;
          }
  meanLoss /= cases;
  mutantMeanLoss /= cases;
  std::printf("  albedo %.4f to %.4f; mean |albedo - 1| %.4f, without the compensation (mutant) %.4f\n", lowest,
              highest, meanLoss, mutantMeanLoss);
  EXPECT_GT(mutantMeanLoss, meanLoss + 0.01);
}

constexpr int kChi2Cases = 3;
const double kChi2Alpha = test::SidakAlpha(0.01, kChi2Cases);

TEST(AnisotropyChi2, SamplerMatchesPdf) {
  std::printf("chi2 of SampleBsdf against BsdfPdf, anisotropic, Sidak alpha %.5f over %d:\n", kChi2Alpha, kChi2Cases);
  const vec3 base(0.8f, 0.5f, 0.2f);
  ExpectSamplerMatchesPdf(Anisotropic(MakeMaterial(base, 1.0f, 0.2f, 1.0f, 1.5f), 0.8f), 0.5f, kUp, &Bsdf::pSpecular,
                          "metal r 0.2 s 0.8, mu_o 0.5", kChi2Alpha, 2800);
  ExpectSamplerMatchesPdf(Anisotropic(MakeMaterial(base, 0.0f, 0.4f, 1.0f, 1.5f), 0.6f), 0.3f, kUp, &Bsdf::pSpecular,
                          "dielectric r 0.4 s 0.6, mu_o 0.3", kChi2Alpha, 2801);
  ExpectSamplerMatchesPdf(Anisotropic(Transmissive(MakeMaterial(base, 0.0f, 0.3f, 1.0f, 1.5f), 1.0f, false), 0.9f),
                          0.7f, kUp, &Bsdf::pTransmission, "thin glass r 0.3 s 0.9, mu_o 0.7", kChi2Alpha, 2802);
}

TEST(Anisotropy, SampleWeightIsFCosOverPdf) {
  ExpectSampleWeightsAreFCosOverPdf("anisotropic", 67, [](Uniform& u) {
    Material m = MakeMaterial(u.Vec3(), u() < 0.5f ? 0.0f : u(), u(), u() < 0.3f ? 0.0f : 1.0f, 1.0f + 2.0f * u());
    if (u() < 0.4f) m = Transmissive(m, u(), u() < 0.5f);
    if (u() < 0.2f) m.clearcoat = u();
    if (u() < 0.2f) m.sheenColor = u.Vec3();
    return std::pair(Anisotropic(m, u()), kUp);
  });
}

}  // namespace
}  // namespace vkpt::internal

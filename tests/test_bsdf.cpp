// Tests of the glTF BSDF (shared/bsdf.h) and the GGX lobe under it (shared/microfacet.h,
// shared/ggx_albedo.h): χ² of the sampler against its pdf (with mutants the test must
// reject), sample weights, reciprocity, white furnaces and the tabulated albedo against an
// independent quadrature. Every test prints its figures and thresholds.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "bsdf_harness.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

using namespace bsdf_test;
using shader::Material;  // the GPU layout the BSDF reads, not the Scene's

constexpr int kChi2Cases = 12;  // the cases of BsdfChi2.SamplerMatchesPdf: Šidák over these
const double kChi2Alpha = test::SidakAlpha(0.01, kChi2Cases);

struct Chi2Case {
  const char* name;
  Material material;
  float muO;
  bool frontFace = true;
};

TEST(BsdfChi2, SamplerMatchesPdf) {
  const Chi2Case cases[] = {
      {"Lambert (specular 0, metallic 0)", MakeMaterial(vec3(0.7f, 0.5f, 0.3f), 0.0f, 0.6f, 0.0f, 1.5f), 0.5f},
      {"GGX metal, roughness 0.2, mu_o 0.5", MakeMaterial(vec3(0.9f, 0.6f, 0.3f), 1.0f, 0.2f, 1.0f, 1.5f), 0.5f},
      {"GGX metal, roughness 0.5, mu_o 0.3", MakeMaterial(vec3(0.9f, 0.6f, 0.3f), 1.0f, 0.5f, 1.0f, 1.5f), 0.3f},
      {"GGX metal, roughness 1.0, mu_o 0.8", MakeMaterial(vec3(0.9f, 0.6f, 0.3f), 1.0f, 1.0f, 1.0f, 1.5f), 0.8f},
      {"glTF mixture m 0.5, rough 0.3, mu_o 0.05", MakeMaterial(vec3(0.8f, 0.3f, 0.1f), 0.5f, 0.3f, 1.0f, 1.5f), 0.05f},
      {"glTF mixture m 0.5, rough 0.3, mu_o 0.5", MakeMaterial(vec3(0.1f, 0.5f, 0.9f), 0.5f, 0.3f, 1.0f, 1.5f), 0.5f},
      {"glTF mixture m 0.5, rough 0.3, mu_o 1.0", MakeMaterial(vec3(0.5f, 0.5f, 0.5f), 0.5f, 0.3f, 1.0f, 1.5f), 1.0f},
      {"glass entering, rough 0.3, mu_o 0.5",
       Transmissive(MakeMaterial(vec3(0.9f, 0.8f, 0.7f), 0.0f, 0.3f, 1.0f, 1.5f), 1.0f, true), 0.5f},
      {"glass entering, rough 0.7, mu_o 0.15",
       Transmissive(MakeMaterial(vec3(1.0f), 0.0f, 0.7f, 1.0f, 1.5f), 1.0f, true), 0.15f},
      {"glass leaving, rough 0.3, mu_o 0.8", Transmissive(MakeMaterial(vec3(1.0f), 0.0f, 0.3f, 1.0f, 1.5f), 1.0f, true),
       0.8f, false},
      {"glass leaving past critical, r 0.2, mu_o 0.3",
       Transmissive(MakeMaterial(vec3(1.0f), 0.0f, 0.2f, 1.0f, 1.5f), 1.0f, true), 0.3f, false},
      {"thin wall T 0.7 m 0.2, rough 0.5, mu_o 0.4",
       Transmissive(MakeMaterial(vec3(0.6f, 0.9f, 0.4f), 0.2f, 0.5f, 1.0f, 1.5f), 0.7f, false), 0.4f},
  };
  static_assert(sizeof(cases) / sizeof(cases[0]) == kChi2Cases);
  std::printf("chi2 of SampleBsdf against BsdfPdf: %d samples, %dx%d (cos, phi) cells, Sidak alpha %.5f over %d\n",
              kChi2Samples, kCosBins, kPhiBins, kChi2Alpha, kChi2Cases);
  uint32_t seed = 100;
  for (const Chi2Case& c : cases) {
    Chi2Result r = BsdfChi2(c.material, c.muO, seed++, c.frontFace);
    PrintChi2(c.name, r, kChi2Alpha);
    EXPECT_GT(r.p, kChi2Alpha) << c.name;
    EXPECT_EQ(r.zeroCellHits, 0) << c.name;
    // The pdf's mass over the upper hemisphere is the fraction of real samples (5σ, plus
    // the quadrature's error).
    EXPECT_NEAR(r.pdfMass, 1.0 - r.noSample, 5.0 * r.massSigma + 2e-3) << c.name;
  }
}

// The χ² routine has teeth: the true sampler for `m` at μo against a wrong density
// pdf(b, ωo, ωi) must be rejected at the same per-case α.
template <class Pdf>
void ExpectWrongPdfRejected(const char* name, const Material& m, float muO, const Pdf& pdf, uint32_t seed) {
  const vec3 wo = Outgoing(muO);
  const Bsdf b = PrepareBsdf(m, wo, true, kUp);
  Chi2Result r = SamplerChi2(
      b, wo, [&](vec3 wi) { return double(pdf(b, wo, wi)); }, seed);
  PrintChi2(name, r, kChi2Alpha);
  EXPECT_LT(r.p, kChi2Alpha) << name;
}

TEST(BsdfChi2, CatchesWrongPdfs) {
  std::printf("chi2 mutants (must give p < %.5f):\n", kChi2Alpha);
  // The visible-normal density D_ωo(h) used as a density of ωi: the reflection Jacobian
  // 1/(4 ωo·h) dropped.
  ExpectWrongPdfRejected(
      "mutant: GGX pdf without 1/(4 wo.h), metal r 0.5", MakeMaterial(vec3(0.9f, 0.6f, 0.3f), 1.0f, 0.5f, 1.0f, 1.5f),
      0.5f,
      [](const Bsdf& b, vec3 wo, vec3 wi) {
        if (wi.z <= 0.0f) return 0.0;
        vec3 h = normalize(wo + wi);
        double ggx = 4.0 * dot(wo, h) * GgxReflectionPdf(wo, wi, b.alpha);
        return b.pSpecular * ggx + (1.0 - b.pSpecular) * CosineHemispherePdf(wi.z);
      },
      200);
  // Classic NDF sampling's density D(h) cos θh / (4 ωo·h) instead of the visible normals'.
  ExpectWrongPdfRejected(
      "mutant: NDF instead of VNDF pdf, metal r 1.0", MakeMaterial(vec3(0.9f, 0.6f, 0.3f), 1.0f, 1.0f, 1.0f, 1.5f),
      0.3f,
      [](const Bsdf& b, vec3 wo, vec3 wi) {
        if (wi.z <= 0.0f) return 0.0;
        vec3 h = normalize(wo + wi);
        double ggx = GgxD(h, b.alpha) * h.z / (4.0 * dot(wo, h));
        return b.pSpecular * ggx + (1.0 - b.pSpecular) * CosineHemispherePdf(wi.z);
      },
      201);
  // The right density, 10 % too high on one half of the hemisphere (y > 0).
  ExpectWrongPdfRejected(
      "mutant: pdf x 1.1 where y > 0, mixture", MakeMaterial(vec3(0.1f, 0.5f, 0.9f), 0.5f, 0.3f, 1.0f, 1.5f), 0.5f,
      [](const Bsdf& b, vec3 wo, vec3 wi) { return BsdfPdf(b, wo, wi) * (wi.y > 0.0f ? 1.1 : 1.0); }, 202);
  // The refraction half vector's density D_ωo(m) used as a density of ωi: Walter's
  // Jacobian |dm/dωi| dropped.
  ExpectWrongPdfRejected(
      "mutant: refraction pdf without |dm/dwi|, r 0.5",
      Transmissive(MakeMaterial(vec3(1.0f), 0.0f, 0.5f, 1.0f, 1.5f), 1.0f, true), 0.6f,
      [](const Bsdf& b, vec3 wo, vec3 wi) {
        if (wi.z >= 0.0f) return double(BsdfPdf(b, wo, wi));
        vec3 h = RefractionHalfVector(wo, wi, b.etap);
        if (h.z == 0.0f) return 0.0;
        double visibleD = 2.0 * dot(wo, h) * GgxD(h, b.alpha) / (wo.z + GgxLambdaRoot(wo.z, b.alpha));
        return b.pTransmission * visibleD;
      },
      203);
}

// ---------------------------------------------------------------------------------------
// Sample weights, reciprocity, range.

Material RandomMaterial(Uniform& u) {
  Material m{};
  m.baseColor = u.Vec3();
  float kind = u();
  m.metallic = kind < 0.3f ? 0.0f : (kind < 0.6f ? 1.0f : u());
  m.roughness = u() < 0.1f ? 0.0f : u();
  m.specular = u() < 0.2f ? 0.0f : (u() < 0.5f ? 1.0f : u());
  m.specularColor = 2.0f * u.Vec3();
  m.ior = u() < 0.1f ? 0.0f : 1.0f + 2.0f * u();
  if (u() < 0.3f) m = Transmissive(m, u() < 0.5f ? 1.0f : u(), u() < 0.7f);
  return m;
}

bool Close(float a, float b, float rel, float abs) {
  return std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b)) + abs;
}
bool Close(vec3 a, vec3 b, float rel, float abs) {
  return Close(a.x, b.x, rel, abs) && Close(a.y, b.y, rel, abs) && Close(a.z, b.z, rel, abs);
}

TEST(Bsdf, SampleWeightIsFCosOverPdf) {
  Uniform u(7);
  int checked = 0, none = 0, bad = 0;
  const int trials = 200000;
  for (int i = 0; i < trials; ++i) {
    const Material m = RandomMaterial(u);
    const vec3 wo = u.Hemisphere();
    const Bsdf b = PrepareBsdf(m, wo, u() < 0.7f, kUp);
    const BsdfSample s = SampleBsdf(b, wo, u.Vec3());
    if (!(s.pdf > 0.0f)) {
      ++none;
      if (s.pdf != 0.0f || s.weight != vec3(0.0f)) ++bad;
      continue;
    }
    ++checked;
    const float pdf = BsdfPdf(b, wo, s.wi);
    const vec3 expected = EvalBsdf(b, wo, s.wi) * std::abs(s.wi.z) / pdf;
    bool ok = Finite(s.weight) && s.weight.x >= 0.0f && s.weight.y >= 0.0f && s.weight.z >= 0.0f &&
              Close(s.pdf, pdf, 1e-6f, 0.0f) && Close(s.weight, expected, 1e-4f, 0.0f) &&
              std::abs(length(s.wi) - 1.0f) < 1e-5f;
    if (!ok && ++bad <= 5)
      ADD_FAILURE() << "weight (" << s.weight.x << ", " << s.weight.y << ", " << s.weight.z << ") expected ("
                    << expected.x << ", " << expected.y << ", " << expected.z << "), pdf " << s.pdf << " vs " << pdf;
  }
  std::printf("sample weight = f cos / pdf (rel 1e-4): %d samples checked, %d without a sample (%.2f%%), %d bad\n",
              checked, none, 100.0 * none / trials, bad);
  EXPECT_EQ(bad, 0);
}

// The BSDF without the rough dielectric's compensation, which scales its lobes by
// 1 / E(μo) and so is not reciprocal by design (bsdf.h): what must be reciprocal.
Bsdf Uncompensated(const Material& m, vec3 wo, bool frontFace) {
  Bsdf b = PrepareBsdf(m, wo, frontFace, kUp);
  b.glassScale = 1.0f;
  return b;
}

TEST(Bsdf, EvalIsReciprocalFiniteNonNegative) {
  Uniform u(8);
  int bad = 0;
  double worst = 0.0;
  const int trials = 200000;
  for (int i = 0; i < trials; ++i) {
    const Material m = RandomMaterial(u);
    const vec3 wo = u.Hemisphere(), wi = u.Hemisphere();
    const bool frontFace = u() < 0.7f;
    const vec3 f = EvalBsdf(Uncompensated(m, wo, frontFace), wo, wi);
    const vec3 g = EvalBsdf(Uncompensated(m, wi, frontFace), wi, wo);
    bool ok = Finite(f) && Finite(g) && f.x >= 0.0f && f.y >= 0.0f && f.z >= 0.0f && Close(f, g, 1e-4f, 1e-6f);
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(double(f[c]) - g[c]) / std::max({1e-6, double(f[c]), double(g[c])}));
    if (!ok && ++bad <= 5)
      ADD_FAILURE() << "f(wo, wi) = (" << f.x << ", " << f.y << ", " << f.z << "), f(wi, wo) = (" << g.x << ", " << g.y
                    << ", " << g.z << ") at mu_o " << wo.z << ", mu_i " << wi.z << ", roughness " << m.roughness
                    << ", metallic " << m.metallic;
  }
  std::printf("reciprocity (rel 1e-4 / abs 1e-6), finite, >= 0: %d pairs, %d bad, worst relative difference %.2e\n",
              trials, bad, worst);
  EXPECT_EQ(bad, 0);
}

// Across a volume's boundary the radiance BTDF obeys f(ωo, ωi) / ηo² = f(ωi, ωo) / ηi²;
// the reverse evaluation happens in the frame of the other side (z and y negated, a
// rotation), from inside. A thin wall is symmetric. (Without the compensation, as above.)
TEST(Bsdf, TransmissionIsReciprocalUpToEtaSquared) {
  Uniform u(10);
  int bad = 0, nonzero = 0;
  double worst = 0.0;
  const int trials = 100000;
  for (int i = 0; i < trials; ++i) {
    const bool volume = u() < 0.7f;
    Material m = MakeMaterial(u.Vec3(), 0.5f * u(), u(), u() < 0.5f ? 1.0f : u(), 1.0f + 1.5f * u(), 2.0f * u.Vec3());
    m = Transmissive(m, u() < 0.5f ? 1.0f : u(), volume);
    const vec3 wo = u.Hemisphere();
    const vec3 wi = -u.Hemisphere();  // below: transmitted
    const bool frontFace = u() < 0.5f;
    const vec3 wo2(wi.x, -wi.y, -wi.z), wi2(wo.x, -wo.y, -wo.z);
    const vec3 f = EvalBsdf(Uncompensated(m, wo, frontFace), wo, wi);
    const vec3 g = EvalBsdf(Uncompensated(m, wo2, !frontFace), wo2, wi2);
    // ηo / ηi: the index on ωo's side over the one on ωi's.
    const float etaO = frontFace ? 1.0f : m.ior, etaI = frontFace ? m.ior : 1.0f;
    const float scale = volume ? (etaI * etaI) / (etaO * etaO) : 1.0f;
    const vec3 gs = g / scale;
    nonzero += MaxComponent(f) > 0.0f;
    bool ok = Finite(f) && Finite(g) && f.x >= 0.0f && f.y >= 0.0f && f.z >= 0.0f && Close(f, gs, 1e-3f, 2e-5f);
    for (int c = 0; c < 3; ++c)
      if (std::max(f[c], gs[c]) > 2e-5f)
        worst = std::max(worst, std::abs(double(f[c]) - gs[c]) / std::max(double(f[c]), double(gs[c])));
    if (!ok && ++bad <= 5)
      ADD_FAILURE() << "f(wo, wi) = (" << f.x << ", " << f.y << ", " << f.z << "), f(wi, wo) eta_o^2/eta_i^2 = ("
                    << gs.x << ", " << gs.y << ", " << gs.z << "), volume " << volume << ", front " << frontFace;
  }
  std::printf(
      "transmission reciprocity f(o,i)/eta_o^2 == f(i,o)/eta_i^2 (rel 1e-3 / abs 2e-5): %d pairs (%d non-zero), "
      "%d bad, worst relative difference above 2e-5 %.2e\n",
      trials, nonzero, bad, worst);
  EXPECT_EQ(bad, 0);
  EXPECT_GT(nonzero, trials / 3);
}

TEST(Bsdf, LambertIsTheSpecialCaseWithoutSpecular) {
  Uniform u(9);
  int bad = 0;
  for (int i = 0; i < 20000; ++i) {
    Material m = RandomMaterial(u);
    m.baseColor = vec3(0.02f) + 0.98f * u.Vec3();  // black has no lobe to choose by albedo
    m.specular = 0.0f;
    m.metallic = 0.0f;
    m.transmission = 0.0f;
    const vec3 wo = u.Hemisphere(), wi = u.Hemisphere();
    const Bsdf b = PrepareBsdf(m, wo, true, kUp);
    const vec3 f = EvalBsdf(b, wo, wi);
    const float pdf = BsdfPdf(b, wo, wi);
    const BsdfSample s = SampleBsdf(b, wo, u.Vec3());
    bool ok = Close(f, m.baseColor * kInvPi, 1e-6f, 0.0f) && Close(pdf, wi.z * kInvPi, 1e-6f, 0.0f) && s.pdf > 0.0f &&
              Close(s.weight, m.baseColor, 1e-5f, 0.0f);
    if (!ok && ++bad <= 5)
      ADD_FAILURE() << "f = (" << f.x << ", " << f.y << ", " << f.z << "), baseColor/pi = (" << m.baseColor.x * kInvPi
                    << ", " << m.baseColor.y * kInvPi << ", " << m.baseColor.z * kInvPi << "), pdf " << pdf
                    << " vs cos/pi " << wi.z * kInvPi;
  }
  std::printf(
      "Lambert: f == baseColor/pi and pdf == cos/pi (rel 1e-6), weight == baseColor (1e-5): 20000 cases, %d bad\n",
      bad);
  EXPECT_EQ(bad, 0);
}

// A white metal (F = 1) reflects everything at every roughness: single scattering plus
// the Kulla-Conty lobe.
TEST(BsdfFurnace, WhiteMetalReflectsEverything) {
  const float alphas[] = {0.01f, 0.0625f, 0.25f, 0.5625f, 1.0f};
  const float mus[] = {0.05f, 0.1f, 0.3f, 0.6f, 1.0f};
  std::printf("white metal furnace, albedo by SampleBsdf (2e5 stratified samples), must be 1 +- 1%%:\n");
  std::printf("  alpha   rough |");
  for (float mu : mus) std::printf("  mu=%-4.2f          ", mu);
  std::printf("\n");
  uint32_t seed = 300;
  double worst = 0.0;
  for (float alpha : alphas) {
    std::printf("  %6.4f  %5.3f |", alpha, std::sqrt(alpha));
    for (float mu : mus) {
      Material m = MakeMaterial(vec3(1.0f), 1.0f, std::sqrt(alpha), 1.0f, 1.5f);
      Albedo a = EstimateAlbedo(m, mu, seed++);
      std::printf("  %.4f +- %.4f  ", a.mean.y, a.stderr_.y);
      worst = std::max(worst, std::abs(a.mean.y - 1.0));
      EXPECT_NEAR(a.mean.x, 1.0, 0.01) << "alpha " << alpha << ", mu " << mu;
      EXPECT_NEAR(a.mean.y, 1.0, 0.01) << "alpha " << alpha << ", mu " << mu;
      EXPECT_NEAR(a.mean.z, 1.0, 0.01) << "alpha " << alpha << ", mu " << mu;
    }
    std::printf("\n");
  }
  std::printf("  largest |albedo - 1| = %.4f (limit 0.01)\n", worst);
}

// A white dielectric over a white base (the coupling is meant to make it sum to one)
// neither creates energy nor loses more than 3 %; coloured materials never exceed one in
// any channel.
TEST(BsdfFurnace, MixtureConservesEnergy) {
  const float roughnesses[] = {0.1f, 0.3f, 0.6f, 1.0f};
  const float mus[] = {0.05f, 0.3f, 1.0f};
  std::printf("white dielectric (base 1, specular 1, ior 1.5) albedo, must be in [0.97, 1 + 3 se]:\n");
  uint32_t seed = 400;
  for (float r : roughnesses) {
    Albedo row[3];
    for (int k = 0; k < 3; ++k) row[k] = EstimateAlbedo(MakeMaterial(vec3(1.0f), 0.0f, r, 1.0f, 1.5f), mus[k], seed++);
    std::printf("  roughness %.2f |", r);
    for (int k = 0; k < 3; ++k) std::printf("  mu %.2f: %.4f +- %.4f", mus[k], row[k].mean.y, row[k].stderr_.y);
    std::printf("\n");
    // White: the three channels agree, so one is checked.
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(row[k].mean.y, 1.0 + 3.0 * row[k].stderr_.y)
          << "a white dielectric reflects more than it receives at roughness " << r << ", mu " << mus[k];
      EXPECT_GE(row[k].mean.y, 0.97) << "roughness " << r << ", mu " << mus[k];
    }
  }
  struct Coloured {
    const char* name;
    Material m;
  };
  const Coloured coloured[] = {
      {"dielectric base (0.9,0.4,0.1), r 0.4", MakeMaterial(vec3(0.9f, 0.4f, 0.1f), 0.0f, 0.4f, 1.0f, 1.5f)},
      {"specularColor (2,1,0.5), base 1, r 0.2",
       MakeMaterial(vec3(1.0f), 0.0f, 0.2f, 1.0f, 1.5f, vec3(2.0f, 1.0f, 0.5f))},
      {"ior 2.5, base (1,1,0.2), r 0.7", MakeMaterial(vec3(1.0f, 1.0f, 0.2f), 0.0f, 0.7f, 1.0f, 2.5f)},
      {"ior 0 (F = 1), base (0.3,1,1), r 0.5", MakeMaterial(vec3(0.3f, 1.0f, 1.0f), 0.0f, 0.5f, 1.0f, 0.0f)},
      {"metallic 0.5, base (1,0.6,0.2), r 0.5", MakeMaterial(vec3(1.0f, 0.6f, 0.2f), 0.5f, 0.5f, 1.0f, 1.5f)},
      {"metal base (1,0.8,0.3), r 0.8", MakeMaterial(vec3(1.0f, 0.8f, 0.3f), 1.0f, 0.8f, 1.0f, 1.5f)},
  };
  const float colouredMus[] = {0.05f, 0.5f, 1.0f};
  std::printf("coloured materials, albedo per channel, must be <= 1 + 3 se:\n");
  for (const Coloured& c : coloured) {
    Albedo row[3];
    for (int k = 0; k < 3; ++k) row[k] = EstimateAlbedo(c.m, colouredMus[k], seed++, 320);
    std::printf("  %-40s", c.name);
    for (int k = 0; k < 3; ++k)
      std::printf(" mu %.2f: (%.4f %.4f %.4f)", colouredMus[k], row[k].mean.x, row[k].mean.y, row[k].mean.z);
    std::printf("\n");
    for (int k = 0; k < 3; ++k)
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_LE(row[k].mean[ch], 1.0 + 3.0 * row[k].stderr_[ch])
            << c.name << ", mu " << colouredMus[k] << ", channel " << ch << ": more than it receives";
  }
}

// White transmissive surfaces (base 1, specular 1, ior 1.5) by SampleBsdf, the renderers'
// sampler: reflected plus transmitted energy is 1 within 0.5 % (plus 3 standard errors)
// at every roughness, from either side of a volume and through a thin wall.
TEST(BsdfFurnace, TransmissionConservesEnergy) {
  struct Case {
    const char* name;
    bool volume, frontFace;
  };
  const Case cases[] = {{"glass, entering", true, true}, {"glass, leaving", true, false}, {"thin wall", false, true}};
  const float roughnesses[] = {0.0f, 0.1f, 0.3f, 0.6f, 1.0f};
  const float mus[] = {0.1f, 0.5f, 1.0f};
  std::printf("white transmissive furnace: reflected + eta^2 transmitted, must be 1 +- (0.005 + 3 se):\n");
  uint32_t seed = 500;
  for (const Case& c : cases)
    for (float r : roughnesses) {
      std::printf("  %-16s r %.1f |", c.name, r);
      for (float mu : mus) {
        const Material m = Transmissive(MakeMaterial(vec3(1.0f), 0.0f, r, 1.0f, 1.5f), 1.0f, c.volume);
        const Albedo a = EstimateAlbedo(m, mu, seed++, 320, c.frontFace);
        std::printf("  mu %.1f: %.4f +- %.4f", mu, a.mean.y, a.stderr_.y);
        EXPECT_NEAR(a.mean.y, 1.0, 0.005 + 3.0 * a.stderr_.y) << c.name << " at r " << r << ", mu " << mu;
      }
      std::printf("\n");
    }
}

// The albedo of a white rough dielectric's two lobes at cos θo = mu, each integrated over
// its own visible-normal samples on a 64 × 512 grid (u2 dense near 1, where the normals
// tilt most): reflection f cos / pdf above, etap² f |cos| / pdf below. Deterministic; a
// few parts in 10⁴ (the weights jump where total internal reflection begins).
double LobeSumAlbedo(const Material& m, float mu, bool frontFace, float* glassScale) {
  const vec3 wo = Outgoing(mu);
  const Bsdf b = PrepareBsdf(m, wo, frontFace, kUp);
  *glassScale = b.glassScale;
  double sum = 0.0;
  const int nPhi = 64, nTail = 512;
  for (int i = 0; i < nPhi; ++i)
    for (int j = 0; j < nTail; ++j) {
      const double x = (j + 0.5) / nTail, jacobian = 4.0 * std::pow(1.0 - x, 3.0);
      const vec3 h = SampleGgxVisibleNormal(wo, b.alpha, (float(i) + 0.5f) / nPhi, float(1.0 - std::pow(1.0 - x, 4.0)));
      const vec3 reflected = 2.0f * dot(wo, h) * h - wo;
      if (reflected.z > 0.0f) {
        const float pdf = GgxReflectionPdf(wo, reflected, b.alpha);
        if (pdf > 0.0f) sum += jacobian * EvalBsdf(b, wo, reflected).y * reflected.z / pdf;
      }
      const vec3 refracted = Refract(wo, h, b.etap);
      if (refracted.z < 0.0f) {
        const float pdf = GgxRefractionPdf(wo, refracted, h, b.etap, b.alpha);
        if (pdf > 0.0f) sum += jacobian * EvalBsdf(b, wo, refracted).y * -refracted.z / pdf * double(b.etap) * b.etap;
      }
    }
  return sum / (double(nPhi) * nTail);
}

// The compensated rough dielectric (bsdf.h: its lobes over their albedo from the table)
// returns 1 within 0.5 % over 64 cosines (16 in a sanitizer build) × both sides ×
// roughness 0.05–1 × ior 1.1, 1.5 and 2.4 — values between the table's grid points, so
// its interpolation is judged.
TEST(BsdfFurnace, RoughDielectricAlbedoIsOneEverywhere) {
  const float iors[] = {1.1f, 1.5f, 2.4f};
  const float roughnesses[] = {0.05f, 0.1f, 0.3f, 0.6f, 1.0f};
  const int cosines = 64 / int(test::kSampleDivisor);
  std::printf("rough dielectric albedo over %d cosines (0.02..1), compensated [uncompensated], must be 1 +- 0.005:\n",
              cosines);
  double worst = 0.0;
  for (float ior : iors)
    for (bool entering : {true, false}) {
      std::printf("  ior %.1f %-8s", ior, entering ? "entering" : "leaving");
      for (float r : roughnesses) {
        double lo = 2.0, hi = 0.0, rawLo = 2.0, rawHi = 0.0;
        for (int k = 0; k < cosines; ++k) {
          const float mu = 0.02f + 0.98f * float(k) / float(cosines - 1);
          float scale = 1.0f;
          const double e = LobeSumAlbedo(Transmissive(MakeMaterial(vec3(1.0f), 0.0f, r, 1.0f, ior), 1.0f, true), mu,
                                         entering, &scale);
          lo = std::min(lo, e), hi = std::max(hi, e);
          rawLo = std::min(rawLo, e / scale), rawHi = std::max(rawHi, e / scale);
          worst = std::max(worst, std::abs(e - 1.0));
          EXPECT_NEAR(e, 1.0, 0.005) << "ior " << ior << (entering ? " entering" : " leaving") << ", roughness " << r
                                     << ", mu " << mu;
        }
        std::printf(" | r %.2f %.3f..%.3f [%.2f..%.2f]", r, lo, hi, rawLo, rawHi);
      }
      std::printf("\n");
    }
  std::printf("  largest |albedo - 1| = %.4f (limit 0.005)\n", worst);
}

// ---------------------------------------------------------------------------------------
// The single-scattering lobe's albedo E(μ) (F = 1) by a quadrature that shares nothing
// with the table's generator (which samples visible normals): a midpoint grid over
// (θi, φi), φ ∈ [0, π] doubled by symmetry, fine enough for lobes down to α = 0.0625.
double LobeAlbedoQuadrature(float mu, float alpha, int n = 1024) {
  const vec3 wo = Outgoing(mu);
  const double dtheta = 0.5 * M_PI / n, dphi = M_PI / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    double theta = (i + 0.5) * dtheta;
    double c = std::cos(theta), s = std::sin(theta);
    double row = 0.0;
    for (int j = 0; j < n; ++j) {
      double phi = (j + 0.5) * dphi;
      vec3 wi(float(s * std::cos(phi)), float(s * std::sin(phi)), float(c));
      row += GgxReflection(wo, wi, alpha);
    }
    sum += row * c * s;
  }
  return 2.0 * sum * dtheta * dphi;
}

TEST(BsdfFurnace, GgxAlbedoTableMatchesQuadrature) {
  const float alphas[] = {0.0625f, 0.25f, 0.5625f, 1.0f};
  const float mus[] = {0.05f, 0.1f, 0.3f, 0.5f, 0.6f, 1.0f};
  std::printf("GGX lobe albedo E(mu), F = 1: quadrature vs table (GgxAlbedo), |diff| <= 2e-3:\n");
  std::map<std::pair<float, float>, double> quadrature;  // (alpha, mu)
  double worst = 0.0;
  for (float alpha : alphas) {
    std::printf("  alpha %6.4f |", alpha);
    for (float mu : mus) {
      double q = quadrature[{alpha, mu}] = LobeAlbedoQuadrature(mu, alpha);
      double t = GgxAlbedo(mu, alpha).x;
      std::printf(" mu %.2f: %.4f/%.4f", mu, q, t);
      worst = std::max(worst, std::abs(q - t));
      EXPECT_NEAR(t, q, 2e-3) << "alpha " << alpha << ", mu " << mu;
    }
    std::printf("\n");
  }
  std::printf("  largest |quadrature - table| = %.5f\n", worst);

  // The engineering-facts figures (numeric, ±0.5 %); E(1) = 1 − ln 2 at α = 1.
  struct Fact {
    float alpha, mu;
    double e;
  };
  const Fact facts[] = {
      {1.0f, 1.0f, 1.0 - std::log(2.0)},
      {1.0f, 0.5f, 0.451},
      {1.0f, 0.1f, 0.762},
      {0.25f, 1.0f, 0.915},
      {0.25f, 0.5f, 0.856},
      {0.25f, 0.1f, 0.891},
      {0.0625f, 1.0f, 0.995},
      {0.0625f, 0.5f, 0.989},
      {0.0625f, 0.1f, 0.900},
      {0.5625f, 1.0f, 0.630},
      {0.5625f, 0.5f, 0.664},
      {0.5625f, 0.1f, 0.849},
  };
  std::printf("  against the engineering facts (+-0.5%%):\n");
  for (const Fact& f : facts) {
    ASSERT_EQ(quadrature.count({f.alpha, f.mu}), 1u);
    double q = quadrature[{f.alpha, f.mu}];
    std::printf("    alpha %6.4f mu %.1f: quadrature %.4f, fact %.4f (%+.2f%%)\n", f.alpha, f.mu, q, f.e,
                100.0 * (q / f.e - 1.0));
    EXPECT_NEAR(q, f.e, 0.005 * f.e) << "alpha " << f.alpha << ", mu " << f.mu;
  }
  const Fact averages[] = {{0.0625f, 0.0f, 0.987}, {0.25f, 0.0f, 0.881}, {0.5625f, 0.0f, 0.655}, {1.0f, 0.0f, 0.409}};
  for (const Fact& f : averages) {
    double t = GgxAverageAlbedo(f.alpha).x;
    std::printf("    alpha %6.4f average: table %.4f, fact %.4f (%+.2f%%)\n", f.alpha, t, f.e, 100.0 * (t / f.e - 1.0));
    EXPECT_NEAR(t, f.e, 0.005 * f.e) << "alpha " << f.alpha;
  }
}

}  // namespace
}  // namespace vkpt::internal

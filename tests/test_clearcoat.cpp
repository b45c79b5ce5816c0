// KHR_materials_clearcoat's lobe (shared/clearcoat.h) in the BSDF (shared/bsdf.h): a white
// coat over a lossless base returns exactly what it receives, the coat alone reflects its
// tabulated albedo, the sampler matches its pdf (χ², with a mutant the test must reject)
// and every sample weighs f cos / pdf, the coat's normal tilted or not.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "bsdf_harness.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

using namespace bsdf_test;
using shader::Material;  // the GPU layout the BSDF reads, not the Scene's

Material Coated(Material m, float coat, float coatRoughness) {
  m.clearcoat = coat;
  m.clearcoatRoughness = coatRoughness;
  return m;
}

// A coat normal tilted from the shading normal by `degrees` about the y axis.
vec3 Tilted(float degrees) {
  const float a = degrees * kPi / 180.0f;
  return vec3(std::sin(a), 0.0f, std::cos(a));
}

const float kMus[] = {0.1f, 0.4f, 1.0f};
const float kCoatRoughness[] = {0.0f, 0.3f, 0.7f, 1.0f};

// A white coat (factor 1 and 0.5) over each lossless base returns 1 at every μo and coat
// roughness: the coat reflects c A_c(μo), the base is given the rest.
TEST(ClearcoatFurnace, WhiteCoatOverALosslessBaseReturnsOne) {
  std::printf("coat over a lossless base, albedo by SampleBsdf (2e5 stratified samples), must be 1 +- 0.5%% + 3 se:\n");
  uint32_t seed = 900;
  double worst = 0.0;
  for (const Base& base : kLosslessBases)
    for (float coat : {1.0f, 0.5f})
      for (float rc : kCoatRoughness)
        for (float mu : kMus) {
          const Albedo a = EstimateAlbedo(Coated(base.material, coat, rc), mu, seed++, kFurnaceStrata);
          const double dev = std::abs(a.mean.y - 1.0);
          worst = std::max(worst, dev);
          std::printf("  %-22s coat %.1f rough %.1f mu %.1f: %.4f +- %.4f\n", base.name, coat, rc, mu, a.mean.y,
                      a.stderr_.y);
          EXPECT_NEAR(a.mean.y, 1.0, 0.005 + 3.0 * a.stderr_.y) << base.name << " coat " << coat << " rough " << rc;
          // A smooth coat over Lambert: exactly 1 but for the GGX table's interpolation.
          if (rc == 0.0f && base.material.specular == 0.0f) {
            EXPECT_NEAR(a.mean.y, 1.0, 2e-4) << "coat " << coat;
          }
        }
  std::printf("  worst deviation from 1: %.4f\n", worst);
}

// The furnace has teeth: without the base's albedo scaling (the base given everything,
// as if the coat took nothing) a coat over white Lambert returns more than 1.
TEST(ClearcoatFurnace, CatchesAMissingAlbedoScaling) {
  for (float mu : kMus) {
    const vec3 wo = Outgoing(mu);
    Bsdf b = PrepareBsdf(Coated(kLosslessBases[0].material, 1.0f, 0.3f), wo, true, kUp);
    b.coatBaseScale = 1.0f;
    const Albedo a = EstimateAlbedo(b, wo, 950);
    std::printf("  mutant without albedo scaling, mu %.1f: %.4f +- %.4f (must exceed 1.005 + 3 se)\n", mu, a.mean.y,
                a.stderr_.y);
    EXPECT_GT(a.mean.y, 1.005 + 3.0 * a.stderr_.y) << "mu " << mu;
  }
}

// ∫ F D V cos θi dωi of a GGX lobe with Schlick's F (F0 `f0`, F90 1) at μo, by midpoint
// quadrature written out here apart from the shaders: over (u, φ) with cos²θh =
// (1 − u) / (1 + (α² − 1) u), which maps D(h) cos θh dωh to du dφ / 2π (so a sharp
// lobe is integrated as finely as a rough one), and dωi = 4 (ωo·h) dωh.
double SchlickLobeQuadrature(float mu, float alpha, double f0, int n = 512) {
  const double so = std::sqrt(1.0 - double(mu) * mu);
  const double a2 = double(alpha) * alpha;
  auto lambda = [&](double c) { return std::sqrt(a2 + (1.0 - a2) * c * c); };
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = (i + 0.5) / n, phi = 2.0 * M_PI * (j + 0.5) / n;
      const double ch = std::sqrt((1.0 - u) / (1.0 + (a2 - 1.0) * u)), sh = std::sqrt(1.0 - ch * ch);
      const double oh = so * sh * std::cos(phi) + mu * ch;  // ωo·h, ωo = (so, 0, μ)
      const double ci = 2.0 * oh * ch - mu;                 // ωi = 2 (ωo·h) h − ωo
      if (oh <= 0.0 || ci <= 0.0) continue;
      const double v = 0.5 / (ci * lambda(mu) + mu * lambda(ci));
      const double f = f0 + (1.0 - f0) * std::pow(1.0 - oh, 5.0);
      sum += f * v * ci * 4.0 * oh / ch;
    }
  return sum / (double(n) * n);
}

// Over a black base the material reflects only its coat: c ∫ F D V cos with F0 = 0.04
// (ior 1.5), by an independent quadrature, at each (coat roughness, μo). The test tells a
// coat of F0 0.05 from it (the teeth: each rough coat's expected value for F0 0.05 must be
// rejected by the same tolerance).
TEST(ClearcoatFurnace, CoatAloneReflectsItsFresnelWeightedLobe) {
  const Material black = MakeMaterial(vec3(0.0f), 0.0f, 0.5f, 0.0f, 1.5f);
  std::printf("coat over black, albedo vs c x quadrature of F D V cos (F0 0.04), within 0.3%% + 3 se:\n");
  uint32_t seed = 1000;
  for (float rc : kCoatRoughness)
    for (float mu : kMus) {
      const float coat = 0.8f;
      const Albedo a = EstimateAlbedo(Coated(black, coat, rc), mu, seed++);
      const double expected = coat * SchlickLobeQuadrature(mu, GgxAlpha(rc), kCoatF0);
      const double wrong = coat * SchlickLobeQuadrature(mu, GgxAlpha(rc), 0.05);
      const double tolerance = 0.003 * expected + 3.0 * a.stderr_.x;
      std::printf("  rough %.1f mu %.1f: %.5f +- %.5f, quadrature %.5f (F0 0.05: %.5f)\n", rc, mu, a.mean.x,
                  a.stderr_.x, expected, wrong);
      EXPECT_NEAR(a.mean.x, expected, tolerance) << "rough " << rc << " mu " << mu;
      EXPECT_GT(std::abs(a.mean.x - wrong), tolerance) << "a wrong Fresnel would pass, rough " << rc << " mu " << mu;
      EXPECT_EQ(a.mean.x, a.mean.z) << "a clear coat reflects every colour alike";
    }
}

constexpr int kCoatChi2Cases = 5;
const double kCoatChi2Alpha = test::SidakAlpha(0.01, kCoatChi2Cases);

struct CoatCase {
  const char* name;
  Material material;
  float muO;
  vec3 coatNormal;
};

const CoatCase kCoatCases[kCoatChi2Cases] = {
    {"coat 1 r 0.1 over red diffuse, mu_o 0.5",
     Coated(MakeMaterial(vec3(0.8f, 0.2f, 0.1f), 0.0f, 0.6f, 1.0f, 1.5f), 1.0f, 0.1f), 0.5f, kUp},
    {"coat 0.6 r 0.4 over metal r 0.3, mu_o 0.2",
     Coated(MakeMaterial(vec3(0.9f, 0.6f, 0.3f), 1.0f, 0.3f, 1.0f, 1.5f), 0.6f, 0.4f), 0.2f, kUp},
    {"coat 1 r 0.2 over glass r 0.3, mu_o 0.5",
     Coated(Transmissive(MakeMaterial(vec3(0.9f), 0.0f, 0.3f, 1.0f, 1.5f), 1.0f, true), 1.0f, 0.2f), 0.5f, kUp},
    {"coat 1 r 0.3 tilted 20 deg, mu_o 0.6", Coated(MakeMaterial(vec3(0.5f), 0.0f, 0.5f, 1.0f, 1.5f), 1.0f, 0.3f), 0.6f,
     Tilted(20.0f)},
    {"coat 0.9 r 0.05 tilted -35 deg, mu_o 0.9",
     Coated(MakeMaterial(vec3(0.2f, 0.7f, 0.3f), 0.5f, 0.8f, 1.0f, 1.5f), 0.9f, 0.05f), 0.9f, Tilted(-35.0f)},
};

TEST(ClearcoatChi2, SamplerMatchesPdf) {
  std::printf("chi2 of SampleBsdf against BsdfPdf with a clear coat, Sidak alpha %.5f over %d:\n", kCoatChi2Alpha,
              kCoatChi2Cases);
  uint32_t seed = 1100;
  for (const CoatCase& c : kCoatCases)
    ExpectSamplerMatchesPdf(c.material, c.muO, c.coatNormal, &Bsdf::pCoat, c.name, kCoatChi2Alpha, seed++);
}

// The test has teeth: the density without the coat lobe's share (its samples counted as
// if they were the cosine lobe's) is rejected.
TEST(ClearcoatChi2, CatchesAPdfWithoutTheCoat) {
  const CoatCase& c = kCoatCases[0];
  ExpectPdfWithoutLobeRejected(c.material, c.muO, c.coatNormal, &Bsdf::pCoat, "mutant: pdf without the coat lobe",
                               kCoatChi2Alpha, 1200);
}

// Random coated materials, coat normals up to 45° from the shading normal, both faces.
TEST(Clearcoat, SampleWeightIsFCosOverPdf) {
  ExpectSampleWeightsAreFCosOverPdf("coated", 17, [](Uniform& u) {
    Material m = MakeMaterial(u.Vec3(), u() < 0.5f ? 0.0f : u(), u(), u() < 0.2f ? 0.0f : 1.0f, 1.0f + 2.0f * u());
    if (u() < 0.3f) m = Transmissive(m, u(), u() < 0.5f);
    m = Coated(m, u() < 0.5f ? 1.0f : u(), u() < 0.1f ? 0.0f : u());
    return std::pair(m, Tilted(90.0f * (u() - 0.5f)));
  });
}

// The coat dims what glows beneath it as the extension says: 1 − c F(cos θ), F0 = 0.04.
TEST(Clearcoat, DimsEmissionByItsFresnel) {
  EXPECT_FLOAT_EQ(CoatTransmittance(1.0f, 1.0f), 0.96f);
  EXPECT_FLOAT_EQ(CoatTransmittance(0.5f, -1.0f), 0.98f);
  EXPECT_FLOAT_EQ(CoatTransmittance(1.0f, 0.0f), 0.0f);
  EXPECT_FLOAT_EQ(CoatTransmittance(0.0f, 0.3f), 1.0f);
}

}  // namespace
}  // namespace vkpt::internal

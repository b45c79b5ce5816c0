// KHR_materials_diffuse_transmission in the BSDF (shared/bsdf.h): on a thin plane without
// a specular layer the diffuse base splits exactly into (1 − dt) baseColor reflected and
// dt diffuseTransmissionColor transmitted; with one, a white material still returns
// what it receives; the lobe is reciprocal, KHR_materials_transmission overrides it, and
// the sampler matches its pdf (χ², with a mutant the test must reject).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "bsdf_harness.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

using namespace bsdf_test;
using shader::Material;  // the GPU layout the BSDF reads, not the Scene's

Material DiffuselyTransmitting(Material m, float share, vec3 color) {
  m.diffuseTransmission = share;
  m.diffuseTransmissionColor = color;
  return m;
}

const vec3 kBase(0.8f, 0.5f, 0.2f), kColor(0.3f, 0.9f, 0.6f);
const float kShares[] = {0.0f, 0.25f, 0.6f, 1.0f};
const float kMus[] = {0.1f, 0.5f, 1.0f};

// Without a specular layer f is (1 − dt) baseColor / π above and dt color / π below,
// exactly, for any pair of directions; the albedos on each side follow within noise.
TEST(DiffuseTransmission, ThinPlaneSplitsTheDiffuseBaseExactly) {
  Uniform u(31);
  uint32_t seed = 1900;
  for (float dt : kShares) {
    const Material m = DiffuselyTransmitting(MakeMaterial(kBase, 0.0f, 0.5f, 0.0f, 1.5f), dt, kColor);
    for (int i = 0; i < 1000; ++i) {
      const vec3 wo = u.Hemisphere(), wi = u.Hemisphere();
      const Bsdf b = PrepareBsdf(m, wo, true, kUp);
      const vec3 up = EvalBsdf(b, wo, wi), down = EvalBsdf(b, wo, MirrorThroughSurface(wi));
      for (int c = 0; c < 3; ++c) {
        ASSERT_NEAR(up[c], (1.0f - dt) * kBase[c] * kInvPi, 1e-7f) << "dt " << dt;
        ASSERT_NEAR(down[c], dt * kColor[c] * kInvPi, 1e-7f) << "dt " << dt;
      }
    }
    for (float mu : kMus) {
      const Albedo a = EstimateAlbedo(m, mu, seed++);
      std::printf("  dt %.2f mu %.1f: reflected (%.4f, %.4f, %.4f), transmitted (%.4f, %.4f, %.4f) +- %.4f\n", dt, mu,
                  a.reflected.x, a.reflected.y, a.reflected.z, a.transmitted.x, a.transmitted.y, a.transmitted.z,
                  a.transmittedStderr.y);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(a.reflected[c], (1.0 - dt) * kBase[c], 3.5 * a.reflectedStderr[c] + 1e-6) << "dt " << dt;
        EXPECT_NEAR(a.transmitted[c], dt * kColor[c], 3.5 * a.transmittedStderr[c] + 1e-6) << "dt " << dt;
      }
    }
  }
}

// A white base passing any share through as white, under a specular layer, a sheen or a
// coat, returns 1 at every μo: the diffuse base's coupling covers both sides.
TEST(DiffuseTransmissionFurnace, WhiteMaterialReturnsOne) {
  std::printf("white diffusely transmitting materials, albedo (both sides), 1 +- 0.5%% + 3 se:\n");
  uint32_t seed = 2000;
  double worst = 0.0;
  for (float roughness : {0.2f, 0.7f})
    for (float dt : {0.3f, 1.0f})
      for (int layer = 0; layer < 3; ++layer)
        for (float mu : kMus) {
          Material m = DiffuselyTransmitting(MakeMaterial(vec3(1.0f), 0.0f, roughness, 1.0f, 1.5f), dt, vec3(1.0f));
          if (layer == 1) m.sheenColor = vec3(1.0f), m.sheenRoughness = 0.5f;
          if (layer == 2) m.clearcoat = 1.0f, m.clearcoatRoughness = 0.3f;
          const Albedo a = EstimateAlbedo(m, mu, seed++, kFurnaceStrata);
          worst = std::max(worst, std::abs(a.mean.y - 1.0));
          std::printf("  rough %.1f dt %.1f %-6s mu %.1f: %.4f +- %.4f (reflected %.4f)\n", roughness, dt,
                      layer == 0 ? "" : (layer == 1 ? "sheen" : "coat"), mu, a.mean.y, a.stderr_.y, a.reflected.y);
          EXPECT_NEAR(a.mean.y, 1.0, 0.005 + 3.0 * a.stderr_.y) << "rough " << roughness << " dt " << dt;
        }
  std::printf("  worst deviation from 1: %.4f\n", worst);
}

// f(ωo, ωi) = f(ωi', ωo') for ωi below: the same pair seen from the other side.
TEST(DiffuseTransmission, IsReciprocal) {
  Uniform u(37);
  for (int i = 0; i < 10000; ++i) {
    const Material m =
        DiffuselyTransmitting(MakeMaterial(u.Vec3(), 0.0f, u(), u() < 0.3f ? 0.0f : 1.0f, 1.0f + u()), u(), u.Vec3());
    const vec3 wo = u.Hemisphere(), wi = MirrorThroughSurface(u.Hemisphere());
    const vec3 fwd = EvalBsdf(PrepareBsdf(m, wo, true, kUp), wo, wi);
    const vec3 back = EvalBsdf(PrepareBsdf(m, MirrorThroughSurface(wi), true, kUp), MirrorThroughSurface(wi),
                               MirrorThroughSurface(wo));
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(fwd[c], back[c], 1e-5f * std::max(fwd[c], 1e-3f)) << i;
  }
}

// KHR_materials_transmission at 1 leaves no diffuse base to pass through: f and pdf are
// those of the same material without diffuse transmission.
TEST(DiffuseTransmission, TransmissionOverridesIt) {
  Uniform u(41);
  for (int i = 0; i < 10000; ++i) {
    const Material glass = Transmissive(MakeMaterial(u.Vec3(), 0.0f, u(), 1.0f, 1.0f + u()), 1.0f, u() < 0.5f);
    const Material both = DiffuselyTransmitting(glass, u(), u.Vec3());
    const vec3 wo = u.Hemisphere(), wi = u() < 0.5f ? u.Hemisphere() : MirrorThroughSurface(u.Hemisphere());
    const Bsdf a = PrepareBsdf(glass, wo, true, kUp), b = PrepareBsdf(both, wo, true, kUp);
    ASSERT_EQ(EvalBsdf(a, wo, wi), EvalBsdf(b, wo, wi)) << i;
    ASSERT_EQ(BsdfPdf(a, wo, wi), BsdfPdf(b, wo, wi)) << i;
  }
}

constexpr int kChi2Cases = 4;
const double kChi2Alpha = test::SidakAlpha(0.01, kChi2Cases);

struct Case {
  const char* name;
  Material material;
  float muO;
};
const Case kCases[kChi2Cases] = {
    {"dt 0.5 without specular, mu_o 0.5",
     DiffuselyTransmitting(MakeMaterial(kBase, 0.0f, 0.5f, 0.0f, 1.5f), 0.5f, kColor), 0.5f},
    {"dt 0.8 under specular r 0.3, mu_o 0.2",
     DiffuselyTransmitting(MakeMaterial(kBase, 0.0f, 0.3f, 1.0f, 1.5f), 0.8f, kColor), 0.2f},
    {"dt 0.3 with transmission 0.5, mu_o 0.7",
     DiffuselyTransmitting(Transmissive(MakeMaterial(kBase, 0.0f, 0.4f, 1.0f, 1.5f), 0.5f, false), 0.3f, kColor), 0.7f},
    {"dt 1 half metallic, mu_o 0.9", DiffuselyTransmitting(MakeMaterial(kBase, 0.5f, 0.6f, 1.0f, 1.5f), 1.0f, kColor),
     0.9f},
};

TEST(DiffuseTransmissionChi2, SamplerMatchesPdf) {
  std::printf("chi2 of SampleBsdf against BsdfPdf with diffuse transmission, Sidak alpha %.5f over %d:\n", kChi2Alpha,
              kChi2Cases);
  uint32_t seed = 2100;
  for (const Case& c : kCases)
    ExpectSamplerMatchesPdf(c.material, c.muO, kUp, &Bsdf::pDiffuseTransmission, c.name, kChi2Alpha, seed++);
}

// The test has teeth: the mixture pdf without the transmitted cosine lobe is rejected.
TEST(DiffuseTransmissionChi2, CatchesAPdfWithoutTheLobe) {
  ExpectPdfWithoutLobeRejected(kCases[1].material, kCases[1].muO, kUp, &Bsdf::pDiffuseTransmission,
                               "mutant: pdf without the transmitted cosine lobe", kChi2Alpha, 2200);
}

TEST(DiffuseTransmission, SampleWeightIsFCosOverPdf) {
  ExpectSampleWeightsAreFCosOverPdf("diffusely transmitting", 43, [](Uniform& u) {
    Material m = MakeMaterial(u.Vec3(), u() < 0.5f ? 0.0f : u(), u(), u() < 0.3f ? 0.0f : 1.0f, 1.0f + 2.0f * u());
    if (u() < 0.3f) m = Transmissive(m, u(), u() < 0.5f);
    if (u() < 0.2f) m.clearcoat = u();
    if (u() < 0.2f) m.sheenColor = u.Vec3();
    return std::pair(DiffuselyTransmitting(m, u(), u.Vec3()), kUp);
  });
}

}  // namespace
}  // namespace vkpt::internal

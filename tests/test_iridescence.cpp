// KHR_materials_iridescence (shared/iridescence.h, shared/bsdf.h): the Gaussian fit of
// the colour matching functions' spectra against a 1 nm integration of the CIE table,
// the film's Fourier series against the Airy sum integrated over the spectrum, its
// limits (a film of the base's index, a vanishing film), the plain material where the
// film is absent, white furnaces over lossless bases, and the sampler (χ², weights).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <vector>

#include "bsdf_harness.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

using namespace bsdf_test;
using shader::Material;  // the GPU layout the BSDF reads, not the Scene's

Material Iridescent(Material m, float factor, float ior, float thickness) {
  m.iridescence = factor;
  m.iridescenceIor = ior;
  m.iridescenceThicknessMin = 100.0f;
  m.iridescenceThickness = thickness;
  return m;
}

using cie::Cmf;

// ∫ cmf(λ) g(λ) dλ / ∫ ȳ dλ at 1 nm.
template <class G>
dvec3 Integrate(const Cmf& cmf, const G& g) {
  dvec3 xyz(0.0);
  for (size_t i = 0; i < cmf.x.size(); ++i) {
    const dvec3 v = g(360.0 + double(i));
    xyz += dvec3(cmf.x[i] * v.x, cmf.y[i] * v.y, cmf.z[i] * v.z);
  }
  return xyz / cmf.yIntegral;
}

// The largest |fit − integral| over OPDs 0 to maxOpd nm and four phase shifts.
template <class Fit>
double WorstSensitivityError(const Cmf& cmf, float maxOpd, const Fit& fit) {
  double worst = 0.0;
  for (float opd = 0.0f; opd <= maxOpd; opd += 5.0f)
    for (float shift : {0.0f, 0.5f * kPi, kPi, 1.5f * kPi}) {
      const dvec3 exact = Integrate(cmf, [&](double nm) { return dvec3(std::cos(2.0 * kPi * opd / nm + shift)); });
      const dvec3 d = abs(dvec3(fit(opd, shift)) - exact);
      worst = std::max({worst, d.x, d.y, d.z});
    }
  return worst;
}

// OPDs up to 1,000 nm are a 400 nm film's first term; up to 3,000 nm its second term
// and thicker films, where the fit's error is larger but its terms are small.
TEST(Iridescence, SensitivityFitMatchesCieIntegration) {
  VKPT_REQUIRE_CMF(cmf);
  const double near = WorstSensitivityError(cmf, 1000.0f, FilmSensitivityXyz);
  const double far = WorstSensitivityError(cmf, 3000.0f, FilmSensitivityXyz);
  std::printf("sensitivity fit - 1 nm CIE integral: worst %.4f to 1000 nm (limit 0.03), %.4f to 3000 nm (limit 0.07)\n",
              near, far);
  EXPECT_LE(near, 0.03);
  EXPECT_LE(far, 0.07);
  // Mutant: the spectra 5 % off in wavelength.
  const double mutant = WorstSensitivityError(
      cmf, 1000.0f, [](float opd, float shift) { return FilmSensitivityXyz(1.05f * opd, shift); });
  std::printf("  mutant (spectra 5 %% off in wavelength): %.4f, must exceed 0.03\n", mutant);
  EXPECT_GT(mutant, 0.03);
}

// The film's reflectance by the Airy sum of its inter-reflections (signed amplitudes
// (n1 − n2) / (n1 + n2) in sign, √R in size, as the series assumes), integrated over the
// spectrum at 1 nm per channel of baseF0 and taken to Rec. 709 balanced to its white, as
// the series is (to the table's white here).
vec3 AiryFilm(const Cmf& cmf, float cosTheta1, float filmIor, float thickness, vec3 baseF0) {
  const vec3 white = XyzToRec709(vec3(Integrate(cmf, [](double) { return dvec3(1.0); })));
  const double cosTheta2 = std::sqrt(1.0 - (1.0 - double(cosTheta1) * cosTheta1) / (double(filmIor) * filmIor));
  const double r12 = FresnelDielectric(cosTheta1, 1.0f, filmIor);
  const double a12 = filmIor > 1.0f ? -std::sqrt(r12) : std::sqrt(r12);
  vec3 rgb;
  for (int c = 0; c < 3; ++c) {
    const float baseIor = IorFromF0(baseF0[c]);
    const double r23 = FresnelDielectric(float(cosTheta2), filmIor, baseIor);
    const double a23 = baseIor > filmIor ? -std::sqrt(r23) : std::sqrt(r23);
    const dvec3 xyz = Integrate(cmf, [&](double nm) {
      const std::complex<double> delay = std::polar(1.0, 2.0 * kPi * 2.0 * filmIor * thickness * cosTheta2 / nm);
      return dvec3(std::norm(a12 + (1.0 - r12) * a23 * delay / (1.0 + a12 * a23 * delay)));
    });
    rgb[c] = XyzToRec709(vec3(xyz))[c] / white[c];
  }
  return rgb;
}

struct FilmCase {
  const char* name;
  float filmIor;
  vec3 baseF0;
  float limit;  // on |series − Airy|
};
// On a metal the series' coefficients are large (both interfaces reflect strongly), and
// so is what the fit's error (above) makes of them.
const FilmCase kFilms[] = {
    {"film 1.3 on dielectric 1.5", 1.3f, vec3(0.04f), 0.02f},
    {"film 1.8 on dielectric 1.5", 1.8f, vec3(0.04f), 0.02f},
    {"film 1.3 on metal (0.95, 0.64, 0.54)", 1.3f, vec3(0.95f, 0.64f, 0.54f), 0.07f},
    {"film 2.0 on metal (0.56, 0.57, 0.58)", 2.0f, vec3(0.56f, 0.57f, 0.58f), 0.07f},
};

// The largest |series − Airy| over cos θ 0.1–1 and thicknesses up to maxThickness nm,
// for a film model `film` (ThinFilmFresnel or a mutant).
template <class Film>
float WorstFilmError(const Cmf& cmf, const FilmCase& f, float maxThickness, const Film& film) {
  float worst = 0.0f;
  for (float mu = 1.0f; mu >= 0.1f - 1e-6f; mu -= 0.1f)
    for (float d = 0.0f; d <= maxThickness; d += 25.0f) {
      const vec3 e = abs(film(mu, f.filmIor, d, f.baseF0) - AiryFilm(cmf, mu, f.filmIor, d, f.baseF0));
      worst = std::max(worst, MaxComponent(e));
    }
  return worst;
}

// Belcour & Barla's series (the fit's integrals) reproduces the spectral Airy sum for
// films up to twice the extension's default maximum.
TEST(Iridescence, SeriesMatchesTheSpectralAirySum) {
  VKPT_REQUIRE_CMF(cmf);
  std::printf("thin film: series - 1 nm Airy integral, cos 0.1-1, thickness 0-800 nm:\n");
  for (const FilmCase& f : kFilms) {
    const float worst = WorstFilmError(cmf, f, 800.0f, ThinFilmFresnel);
    std::printf("  %-38s worst %.4f (limit %.2f)\n", f.name, worst, f.limit);
    EXPECT_LE(worst, f.limit) << f.name;
  }
  // Mutant: the optical path without the film's index (a wrong OPD).
  const float mutant = WorstFilmError(cmf, kFilms[0], 800.0f, [](float mu, float ior, float d, vec3 f0) {
    return ThinFilmFresnel(mu, ior, d / ior, f0);
  });
  std::printf("  mutant (OPD without the film's index): %.4f, must exceed 0.02\n", mutant);
  EXPECT_GT(mutant, 0.02f);
}

// A film of the base's own index is no boundary: the series gives the base's Fresnel
// exactly, at every angle and thickness.
TEST(Iridescence, FilmOfTheBasesIndexIsTheBasesFresnel) {
  float worst = 0.0f;
  for (float n : {1.2f, 1.5f, 2.4f}) {
    const float f0 = ((n - 1.0f) / (n + 1.0f)) * ((n - 1.0f) / (n + 1.0f));
    for (float mu = 0.01f; mu <= 1.0f; mu += 0.01f)
      for (float d : {50.0f, 250.0f, 400.0f, 1200.0f}) {
        const vec3 f = ThinFilmFresnel(mu, n, d, vec3(f0));
        worst = std::max(worst, MaxComponent(abs(f - vec3(FresnelDielectric(mu, 1.0f, n)))));
      }
  }
  std::printf("film of the base's index - the base's Fresnel: worst %.2e (limit 1e-6)\n", worst);
  EXPECT_LE(worst, 1e-6f);
}

// As the film vanishes, its reflectance at normal incidence tends to the base's Fresnel
// (to the series' last terms); kFilmWhite is the fit's white. The phase shifts decide this limit: with either of them
// wrong, a 1.3 film on a 1.5 base reflects 0.004 instead of 0.04.
TEST(Iridescence, VanishingFilmIsTheBasesFresnel) {
  const vec3 white = XyzToRec709(FilmSensitivityXyz(0.0f, 0.0f));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(kFilmWhite[c], white[c], 1e-6f);
  float worst = 0.0f;
  for (const FilmCase& f : kFilms) {
    const vec3 film = ThinFilmFresnel(1.0f, f.filmIor, 1e-3f, f.baseF0);
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(film[c] - FresnelDielectric(1.0f, 1.0f, IorFromF0(f.baseF0[c]))));
  }
  std::printf("film of 0.001 nm at normal incidence - the base's Fresnel: worst %.5f (limit 0.002)\n", worst);
  EXPECT_LE(worst, 0.002f);
}

// Factor 0, or a film of thickness 0, is the plain material, bit for bit: f, pdf and
// samples.
TEST(Iridescence, AbsentFilmIsThePlainMaterial) {
  int i = 0;
  ExpectSameBsdf(47, 20000, [&](Uniform& u) {
    Material plain = MakeMaterial(u.Vec3(), u() < 0.5f ? 0.0f : u(), u(), u() < 0.2f ? 0.0f : 1.0f, 1.0f + u());
    if (u() < 0.3f) plain = Transmissive(plain, u(), u() < 0.5f);
    const Material film = i++ % 2 == 0 ? Iridescent(plain, 0.0f, 1.3f, 400.0f) : Iridescent(plain, u(), 1.3f, 0.0f);
    return std::pair(plain, film);
  });
}

// A film over a white metal and in a white thin glass wall keeps every channel's energy
// (it only moves light between reflection and transmission); over a white dielectric
// with a white base, the diffuse base takes 1 − max F, so the largest channel returns 1
// for a mirror-smooth layer, where the film's albedo is exact, and the others less.
TEST(IridescenceFurnace, WhiteLayersReturnOne) {
  std::printf("iridescent white materials (film 1.3, 400 nm), albedo:\n");
  uint32_t seed = 2300;
  for (float mu : {0.2f, 0.6f, 1.0f}) {
    for (float roughness : {0.05f, 0.5f}) {
      const Material metal = Iridescent(MakeMaterial(vec3(1.0f), 1.0f, roughness, 1.0f, 1.5f), 1.0f, 1.3f, 400.0f);
      const Material wall = Iridescent(Transmissive(MakeMaterial(vec3(1.0f), 0.0f, roughness, 1.0f, 1.5f), 1.0f, false),
                                       1.0f, 1.3f, 400.0f);
      for (const auto& [name, m] : {std::pair("metal", metal), std::pair("thin wall", wall)}) {
        const Albedo a = EstimateAlbedo(m, mu, seed++, kFurnaceStrata);
        std::printf("  %-9s r %.2f mu %.1f: (%.4f, %.4f, %.4f) +- %.4f, limit 1 +- 0.5%% + 3 se\n", name, roughness, mu,
                    a.mean.x, a.mean.y, a.mean.z, a.stderr_.y);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.mean[c], 1.0, 0.005 + 3.0 * a.stderr_[c]) << name << " mu " << mu;
      }
    }
    const Material dielectric = Iridescent(MakeMaterial(vec3(1.0f), 0.0f, 0.0f, 1.0f, 1.5f), 1.0f, 1.3f, 400.0f);
    const Albedo a = EstimateAlbedo(dielectric, mu, seed++, kFurnaceStrata);
    const double largest = std::max({a.mean.x, a.mean.y, a.mean.z});
    std::printf("  dielectric mirror-smooth mu %.1f: (%.4f, %.4f, %.4f) +- %.4f, largest 1 +- 0.5%% + 3 se\n", mu,
                a.mean.x, a.mean.y, a.mean.z, a.stderr_.y);
    EXPECT_NEAR(largest, 1.0, 0.005 + 3.0 * a.stderr_.y) << "mu " << mu;
  }
}

// What a rough film's albedo estimate misses: the largest channel of a white dielectric
// with a film over a white base, against 1 (printed for docs/limits.md; bounded).
TEST(IridescenceFurnace, RoughFilmsStayNearOne) {
  std::printf("iridescent white dielectric over a white base, largest channel (limit 1 +- 3%%):\n");
  uint32_t seed = 2400;
  for (float roughness : {0.3f, 0.6f, 1.0f})
    for (float thickness : {250.0f, 400.0f, 800.0f})
      for (float mu : {0.2f, 1.0f}) {
        const Material m = Iridescent(MakeMaterial(vec3(1.0f), 0.0f, roughness, 1.0f, 1.5f), 1.0f, 1.3f, thickness);
        const Albedo a = EstimateAlbedo(m, mu, seed++, kFurnaceStrata / 2);
        const double largest = std::max({a.mean.x, a.mean.y, a.mean.z});
        std::printf("  r %.1f d %3.0f nm mu %.1f: %.4f +- %.4f\n", roughness, thickness, mu, largest, a.stderr_.y);
        EXPECT_NEAR(largest, 1.0, 0.03 + 3.0 * a.stderr_.y);
      }
}

// Mutant: without the diffuse base's scaling (the coupling Schlick's layer alone would
// have), a mirror-smooth white iridescent dielectric returns more or less than 1.
TEST(IridescenceFurnace, CatchesABaseWithoutTheFilmsScaling) {
  const Material m = Iridescent(MakeMaterial(vec3(1.0f), 0.0f, 0.0f, 1.0f, 1.5f), 1.0f, 1.3f, 400.0f);
  double worst = 0.0;
  uint32_t seed = 2500;
  for (float mu : {0.2f, 0.6f, 1.0f}) {
    const vec3 wo = Outgoing(mu);
    Bsdf b = PrepareBsdf(m, wo, true, kUp);
    Bsdf plain = PrepareBsdf(Iridescent(m, 0.0f, 1.3f, 400.0f), wo, true, kUp);
    b.couplingO = plain.couplingO;
    const Albedo a = EstimateAlbedo(b, wo, seed++, kFurnaceStrata);
    worst = std::max(worst, std::abs(std::max({a.mean.x, a.mean.y, a.mean.z}) - 1.0));
  }
  std::printf("mutant (base without the film's scaling): worst |largest - 1| %.4f, must exceed 0.01\n", worst);
  EXPECT_GT(worst, 0.01);
}

constexpr int kChi2Cases = 3;
const double kChi2Alpha = test::SidakAlpha(0.01, kChi2Cases);

TEST(IridescenceChi2, SamplerMatchesPdf) {
  std::printf("chi2 of SampleBsdf against BsdfPdf with a film, Sidak alpha %.5f over %d:\n", kChi2Alpha, kChi2Cases);
  const vec3 base(0.8f, 0.5f, 0.2f);
  ExpectSamplerMatchesPdf(Iridescent(MakeMaterial(base, 0.0f, 0.3f, 1.0f, 1.5f), 1.0f, 1.3f, 400.0f), 0.3f, kUp,
                          &Bsdf::pSpecular, "film on dielectric r 0.3, mu_o 0.3", kChi2Alpha, 2600);
  ExpectSamplerMatchesPdf(Iridescent(MakeMaterial(base, 0.6f, 0.5f, 1.0f, 1.5f), 0.7f, 1.8f, 300.0f), 0.8f, kUp,
                          &Bsdf::pSpecular, "film on half metal r 0.5, mu_o 0.8", kChi2Alpha, 2601);
  ExpectSamplerMatchesPdf(
      Iridescent(Transmissive(MakeMaterial(base, 0.0f, 0.4f, 1.0f, 1.5f), 0.8f, true), 1.0f, 1.3f, 600.0f), 0.6f, kUp,
      &Bsdf::pTransmission, "film on glass r 0.4, mu_o 0.6", kChi2Alpha, 2602);
}

TEST(Iridescence, SampleWeightIsFCosOverPdf) {
  ExpectSampleWeightsAreFCosOverPdf("iridescent", 53, [](Uniform& u) {
    Material m = MakeMaterial(u.Vec3(), u() < 0.5f ? 0.0f : u(), u(), u() < 0.3f ? 0.0f : 1.0f, 1.0f + 2.0f * u());
    if (u() < 0.3f) m = Transmissive(m, u(), u() < 0.5f);
    if (u() < 0.2f) m.clearcoat = u();
    if (u() < 0.2f) m.sheenColor = u.Vec3();
    if (u() < 0.2f) m.diffuseTransmission = u(), m.diffuseTransmissionColor = u.Vec3();
    return std::pair(Iridescent(m, u(), 1.0f + u(), 1000.0f * u()), kUp);
  });
}

}  // namespace
}  // namespace vkpt::internal

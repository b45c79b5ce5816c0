// The BSDF tests' harness (test_bsdf.cpp, test_clearcoat.cpp): materials, directions
// and uniforms, χ² of a sampler against a density (pbrt-v4 / Mitsuba style), and the
// albedo ∫ f cos dω by importance sampling.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "shared/bsdf.h"
#include "test_util.h"

namespace vkpt::internal::bsdf_test {

using namespace shader;
using shader::Material;  // the GPU layout the BSDF reads, not the Scene's

const vec3 kUp(0.0f, 0.0f, 1.0f);  // the shading normal: a clear coat's normal unless a test tilts it

inline Material MakeMaterial(vec3 baseColor, float metallic, float roughness, float specular, float ior,
                             vec3 specularColor = vec3(1.0f)) {
  Material m{};
  m.baseColor = baseColor;
  m.metallic = metallic;
  m.roughness = roughness;
  m.specular = specular;
  m.ior = ior;
  m.specularColor = specularColor;
  return m;
}

// KHR_materials_transmission `t`, and KHR_materials_volume (a thickness) if `volume`.
inline Material Transmissive(Material m, float t, bool volume) {
  m.transmission = t;
  m.flags = volume ? kMaterialVolume : 0u;
  return m;
}

// The direction at cos θ = mu in the xz plane.
inline vec3 Outgoing(float mu) { return vec3(std::sqrt(std::max(0.0f, 1.0f - mu * mu)), 0.0f, mu); }

// Independent uniforms in [0, 1) (std::uniform_real_distribution may round up to 1).
struct Uniform {
  std::mt19937 rng;
  std::uniform_real_distribution<float> dist{0.0f, 1.0f};
  explicit Uniform(uint32_t seed) : rng(seed) {}
  float operator()() { return std::min(dist(rng), kOneMinusEpsilon); }
  vec3 Vec3() {
    float a = (*this)();
    float b = (*this)();
    float c = (*this)();
    return vec3(a, b, c);
  }
  // A direction on the upper hemisphere, uniform in (cos θ, φ), cos θ ≥ 1e-3.
  vec3 Hemisphere() {
    float mu = std::max((*this)(), 1e-3f);
    float phi = 2.0f * kPi * (*this)();
    float s = std::sqrt(1.0f - mu * mu);
    return vec3(s * std::cos(phi), s * std::sin(phi), mu);
  }
};

inline bool Finite(vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// ---------------------------------------------------------------------------------------
// χ² of a sampler against a density, pbrt-v4 / Mitsuba style: directions binned on a
// (cos θ, φ) grid of odd resolution over the upper hemisphere, or the whole sphere for
// transmissive materials; a cell's expected count is the density integrated over it
// (kSub × kSub midpoints). Samples with pdf 0 are "no sample" and left out; the expected
// counts are conditioned on the number of real samples (so the statistic tests the
// density's shape), and its total mass is checked separately: ∫ pdf over the grid must
// equal the fraction of real samples.

constexpr int kCosBins = 33, kPhiBins = 65, kSub = 16;
constexpr int kChi2Samples = 1000000;

struct Chi2Result {
  double chi2 = 0.0, p = 0.0;
  int dof = 0;
  double noSample = 0.0;   // fraction of samples with pdf 0
  double pdfMass = 0.0;    // ∫ pdf dω over the grid (numeric)
  double massSigma = 0.0;  // binomial standard error of 1 − noSample
  long zeroCellHits = 0;   // samples in cells whose expected count is 0
};

// The grid's cos θ runs over [zMin, 1]: zMin 0 (hemisphere) or −1 (sphere).
inline int CellOf(vec3 wi, double zMin) {
  double z = std::clamp(double(wi.z), zMin, 1.0);
  double phi = std::atan2(double(wi.y), double(wi.x));
  if (phi < 0.0) phi += 2.0 * M_PI;
  int iz = std::min(kCosBins - 1, int((z - zMin) / (1.0 - zMin) * kCosBins));
  int ip = std::min(kPhiBins - 1, int(phi / (2.0 * M_PI) * kPhiBins));
  return iz * kPhiBins + ip;
}

// sample(u, &wi) returns false for "no sample"; pdf(wi) is the solid-angle density.
template <class Sample, class Pdf>
inline Chi2Result RunChi2(const Sample& sample, const Pdf& pdf, uint32_t seed, double zMin = 0.0,
                          int samples = kChi2Samples) {
  const int cells = kCosBins * kPhiBins;
  std::vector<double> observed(cells, 0.0), mass(cells, 0.0);
  Uniform uniform(seed);
  long none = 0;
  for (int i = 0; i < samples; ++i) {
    vec3 wi;
    if (!sample(uniform.Vec3(), &wi)) {
      ++none;
      continue;
    }
    observed[CellOf(wi, zMin)] += 1.0;
  }
  const double dz = (1.0 - zMin) / kCosBins, dphi = 2.0 * M_PI / kPhiBins;
  double total = 0.0;
  for (int iz = 0; iz < kCosBins; ++iz)
    for (int ip = 0; ip < kPhiBins; ++ip) {
      double sum = 0.0;
      for (int a = 0; a < kSub; ++a)
        for (int b = 0; b < kSub; ++b) {
          double z = zMin + (iz + (a + 0.5) / kSub) * dz;
          double phi = (ip + (b + 0.5) / kSub) * dphi;
          double s = std::sqrt(1.0 - z * z);
          sum += pdf(vec3(float(s * std::cos(phi)), float(s * std::sin(phi)), float(z)));
        }
      mass[iz * kPhiBins + ip] = sum * dz * dphi / (kSub * kSub);
      total += mass[iz * kPhiBins + ip];
    }
  Chi2Result r;
  const double real = double(samples - none);
  r.noSample = double(none) / samples;
  r.pdfMass = total;
  r.massSigma = std::sqrt(std::max(r.noSample * (1.0 - r.noSample), 1.0 / samples) / samples);
  std::vector<double> obs, exp;
  for (int k = 0; k < cells; ++k) {
    if (mass[k] <= 0.0) {
      r.zeroCellHits += long(observed[k]);
      continue;
    }
    obs.push_back(observed[k]);
    exp.push_back(real * mass[k] / total);
  }
  r.p = test::ChiSquareTest(obs, exp, &r.chi2, &r.dof);
  return r;
}

inline void PrintChi2(const std::string& name, const Chi2Result& r, double alpha) {
  std::printf("  %-44s chi2 = %8.1f  dof = %4d  p = %.4f (alpha %.5f)  no sample %6.3f%%  1 - pdf mass %6.3f%%\n",
              name.c_str(), r.chi2, r.dof, r.p, alpha, 100.0 * r.noSample, 100.0 * (1.0 - r.pdfMass));
}

// χ² of SampleBsdf for `b` at ωo against the density `pdf` (BsdfPdf, or a mutant), over
// the whole sphere if the material transmits.
template <class Pdf>
Chi2Result SamplerChi2(const Bsdf& b, vec3 wo, const Pdf& pdf, uint32_t seed) {
  return RunChi2(
      [&](vec3 u, vec3* wi) {
        BsdfSample s = SampleBsdf(b, wo, u);
        *wi = s.wi;
        return s.pdf > 0.0f;
      },
      pdf, seed, Transmits(b) ? -1.0 : 0.0);
}

// χ² of SampleBsdf against BsdfPdf for one material and ωo, on the front face or inside.
inline Chi2Result BsdfChi2(const Material& m, float muO, uint32_t seed, bool frontFace = true) {
  const vec3 wo = Outgoing(muO);
  const Bsdf b = PrepareBsdf(m, wo, frontFace, kUp);
  return SamplerChi2(
      b, wo, [&](vec3 wi) { return double(BsdfPdf(b, wo, wi)); }, seed);
}

// The lossless bases that layers (clear coat, sheen) are tested over: white Lambert
// (specular 0), a white rough metal, a white dielectric (diffuse under specular: their
// coupling sums to one) and a white rough glass boundary (both sides compensated).
struct Base {
  const char* name;
  Material material;
};
const Base kLosslessBases[] = {
    {"white Lambert", MakeMaterial(vec3(1.0f), 0.0f, 0.5f, 0.0f, 1.5f)},
    {"white metal r 0.5", MakeMaterial(vec3(1.0f), 1.0f, 0.5f, 1.0f, 1.5f)},
    {"white dielectric r 0.4", MakeMaterial(vec3(1.0f), 0.0f, 0.4f, 1.0f, 1.5f)},
    {"white glass r 0.3", Transmissive(MakeMaterial(vec3(1.0f), 0.0f, 0.3f, 1.0f, 1.5f), 1.0f, true)},
};

// ---------------------------------------------------------------------------------------
// Albedo ∫ f cos dω by importance sampling with SampleBsdf, stratified in (u.y, u.z).

struct Albedo {
  dvec3 mean, stderr_;
  dvec3 reflected, reflectedStderr;      // the part of mean that leaves above the surface
  dvec3 transmitted, transmittedStderr;  // and below it
};

// Transmitted samples count etap² times: radiance / η² is what a boundary conserves, so
// this is the share of the energy arriving along ωo that leaves along either side.
inline Albedo EstimateAlbedo(const Bsdf& b, vec3 wo, uint32_t seed, int strata = 448) {
  Uniform u(seed);
  dvec3 sum(0.0), sum2(0.0), above(0.0), above2(0.0);
  for (int i = 0; i < strata; ++i)
    for (int j = 0; j < strata; ++j) {
      float lobe = u();
      float u1 = std::min((float(i) + u()) / float(strata), kOneMinusEpsilon);
      float u2 = std::min((float(j) + u()) / float(strata), kOneMinusEpsilon);
      BsdfSample s = SampleBsdf(b, wo, vec3(lobe, u1, u2));
      dvec3 w = s.pdf > 0.0f ? dvec3(s.weight) : dvec3(0.0);
      if (s.wi.z < 0.0f) w *= double(b.etap) * b.etap;
      if (s.wi.z > 0.0f) above += w, above2 += w * w;
      sum += w;
      sum2 += w * w;
    }
  const double n = double(strata) * strata;
  Albedo a;
  a.mean = sum / n;
  a.reflected = above / n;
  a.transmitted = a.mean - a.reflected;
  a.reflectedStderr = sqrt(max(above2 / n - a.reflected * a.reflected, dvec3(0.0)) / (n - 1.0));
  const dvec3 below2 = sum2 - above2;
  a.transmittedStderr = sqrt(max(below2 / n - a.transmitted * a.transmitted, dvec3(0.0)) / (n - 1.0));
  // The iid standard error: an upper bound for the stratified estimate.
  a.stderr_ = sqrt(max(sum2 / n - a.mean * a.mean, dvec3(0.0)) / (n - 1.0));
  return a;
}

// 2e5 stratified samples per albedo in the layers' furnaces; 4× fewer in a sanitizer
// build (test_util.h).
const int kFurnaceStrata = test::kSampleDivisor == 1 ? 448 : 224;

inline Albedo EstimateAlbedo(const Material& m, float muO, uint32_t seed, int strata = 448, bool frontFace = true) {
  const vec3 wo = Outgoing(muO);
  return EstimateAlbedo(PrepareBsdf(m, wo, frontFace, kUp), wo, seed, strata);
}

// ---------------------------------------------------------------------------------------
// Two materials from `make(u)` (a pair) that must be one BSDF bit for bit: f, pdf and
// sample weights for `n` random ωo, ωi on either side and either face.
template <class Make>
void ExpectSameBsdf(uint32_t seed, int n, const Make& make) {
  Uniform u(seed);
  for (int i = 0; i < n; ++i) {
    const auto [m1, m2] = make(u);
    const vec3 wo = u.Hemisphere(), wi = u() < 0.5f ? u.Hemisphere() : MirrorThroughSurface(u.Hemisphere());
    const bool front = u() < 0.7f;
    const Bsdf a = PrepareBsdf(m1, wo, front, kUp), b = PrepareBsdf(m2, wo, front, kUp);
    ASSERT_EQ(EvalBsdf(a, wo, wi), EvalBsdf(b, wo, wi)) << i;
    ASSERT_EQ(BsdfPdf(a, wo, wi), BsdfPdf(b, wo, wi)) << i;
    const vec3 v(u(), u(), u());
    ASSERT_EQ(SampleBsdf(a, wo, v).weight, SampleBsdf(b, wo, v).weight) << i;
  }
}

// ---------------------------------------------------------------------------------------
// Every sample's weight is f cos / pdf, its pdf BsdfPdf's, for `n` random materials and
// shading normals from `make(u)` (a Material and the coat's normal), ωo on the upper
// hemisphere, either face.

struct SampleWeightCheck {
  int checked = 0, bad = 0;
};

inline bool Near(float a, float b) { return std::abs(a - b) <= 1e-4f * std::max(a, b); }

template <class Make>
SampleWeightCheck CheckSampleWeights(Uniform& u, int n, const Make& make) {
  SampleWeightCheck c;
  for (int i = 0; i < n; ++i) {
    const auto [m, coatNormal] = make(u);
    const vec3 wo = u.Hemisphere();
    const Bsdf b = PrepareBsdf(m, wo, u() < 0.7f, coatNormal);
    const BsdfSample s = SampleBsdf(b, wo, u.Vec3());
    if (!(s.pdf > 0.0f)) {
      c.bad += s.pdf != 0.0f || s.weight != vec3(0.0f);
      continue;
    }
    ++c.checked;
    const float pdf = BsdfPdf(b, wo, s.wi);
    const vec3 f = EvalBsdf(b, wo, s.wi);
    const vec3 expected = f * std::abs(s.wi.z) / pdf;
    const bool ok = Finite(s.weight) && MaxComponent(f) >= 0.0f && std::abs(s.pdf - pdf) <= 1e-6f * pdf &&
                    Near(s.weight.x, expected.x) && Near(s.weight.y, expected.y) && Near(s.weight.z, expected.z);
    if (!ok && ++c.bad <= 5) ADD_FAILURE() << "pdf " << s.pdf << " vs " << pdf << ", weight.x " << s.weight.x;
  }
  return c;
}

// CheckSampleWeights over 100,000 materials from `make`, printed and expected flawless.
template <class Make>
void ExpectSampleWeightsAreFCosOverPdf(const char* what, uint32_t seed, const Make& make) {
  Uniform u(seed);
  const SampleWeightCheck c = CheckSampleWeights(u, 100000, make);
  std::printf("%s sample weight = f cos / pdf: %d samples checked, %d bad\n", what, c.checked, c.bad);
  EXPECT_GT(c.checked, 80000);
  EXPECT_EQ(c.bad, 0);
}

// SampleBsdf of `m` at μo against BsdfPdf (χ² above α, no sample in a cell of density 0,
// the density's mass that of the real samples), the material's `lobe` sampled.
inline void ExpectSamplerMatchesPdf(const Material& m, float muO, vec3 coatNormal, float Bsdf::*lobe, const char* name,
                                    double alpha, uint32_t seed) {
  const vec3 wo = Outgoing(muO);
  const Bsdf b = PrepareBsdf(m, wo, true, coatNormal);
  ASSERT_GT(b.*lobe, 0.0f) << name;
  const Chi2Result r = SamplerChi2(
      b, wo, [&](vec3 wi) { return double(BsdfPdf(b, wo, wi)); }, seed);
  PrintChi2(name, r, alpha);
  EXPECT_GT(r.p, alpha) << name;
  EXPECT_EQ(r.zeroCellHits, 0) << name;
  EXPECT_NEAR(r.pdfMass, 1.0 - r.noSample, 5.0 * r.massSigma + 2e-3) << name;
}

// The χ² tests' teeth: SampleBsdf of `m` at μo against the pdf of the same material with
// `lobe`'s probability set to 0 (its samples counted as the cosine lobe's) must be rejected.
inline void ExpectPdfWithoutLobeRejected(const Material& m, float muO, vec3 coatNormal, float Bsdf::*lobe,
                                         const char* name, double alpha, uint32_t seed) {
  const vec3 wo = Outgoing(muO);
  const Bsdf b = PrepareBsdf(m, wo, true, coatNormal);
  Bsdf mutant = b;
  mutant.*lobe = 0.0f;
  const Chi2Result r = SamplerChi2(
      b, wo, [&](vec3 wi) { return double(BsdfPdf(mutant, wo, wi)); }, seed);
  PrintChi2(name, r, alpha);
  EXPECT_LT(r.p, alpha) << name;
}

}  // namespace vkpt::internal::bsdf_test

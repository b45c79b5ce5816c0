// KHR_materials_dispersion (shared/dispersion.h, path.h): the index against the Abbe
// number at the Fraunhofer lines, the hero wavelength's bins against the CIE table and
// their weights averaging to white, a dispersive glass sphere in a white furnace, a
// prism's spectrum against Snell's law on both backends, and dispersion 0 (or a
// dispersive material no ray reaches) leaving the image bit for bit as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "cpu/path_tracer.h"
#include "gpu_test.h"
#include "image/image_compare.h"
#include "path_variants.h"
#include "render/render_scene.h"
#include "shared/dispersion.h"
#include "shared/iridescence.h"
#include "test_util.h"
#include "vk/vk_renderer.h"

namespace vkpt::internal {
namespace {

using shader::CauchySpread;
using shader::DispersiveIor;
using shader::kWavelengthBins;

// The index in double, from the Cauchy coefficients the extension derives: B from the
// Abbe number and the F and C lines, A from n(λd) = nd.
double CauchyIor(double nd, double dispersion, double nm) {
  const double vd = 20.0 / dispersion, d = shader::kLineD, f = shader::kLineF, c = shader::kLineC;
  const double b = (nd - 1.0) / (vd * (1.0 / (f * f) - 1.0 / (c * c)));
  return std::max(nd - b / (d * d) + b / (nm * nm), 1.0);
}

TEST(Dispersion, IndexMeetsTheAbbeNumberAtTheFraunhoferLines) {
  // Vd is (nd − 1)/(nF − nC): the spread between F and C must be 1, and 0 at d.
  const double atD = CauchySpread(shader::kLineD);
  const double fToC = double(CauchySpread(shader::kLineF)) - double(CauchySpread(shader::kLineC));
  // A mutant of the equation, 1/λ for 1/λ²: it meets the Abbe number too, but not the
  // index between the lines, which the comparison with CauchyIor below checks.
  auto spreadMutant = [](double nm) {
    const double d = shader::kLineD;
    return (d / nm - 1.0) / (d / shader::kLineF - d / shader::kLineC);
  };
  const double mutantAt400 = spreadMutant(400.0) - double(CauchySpread(400.0f));
  double worstIor = 0.0, worstExtension = 0.0;
  for (double nd : {1.1, 1.33, 1.5, 1.76, 2.42})
    for (double dispersion : {0.1, 0.33, 1.0, 5.0})
      for (double nm = 380.0; nm <= 780.0; nm += 5.0) {
        const double n = DispersiveIor(float(nd), float(dispersion), float(nm));
        worstIor = std::max(worstIor, std::abs(n - CauchyIor(nd, dispersion, nm)));
        // The extension's rounded form, relative to the spread nF − nC it sets.
        const double rounded = std::max(nd + (nd - 1.0) * dispersion / 20.0 * (523655.0 / (nm * nm) - 1.5168), 1.0);
        worstExtension = std::max(worstExtension, std::abs(n - rounded) / ((nd - 1.0) * dispersion / 20.0));
      }
  std::printf(
      "Cauchy spread at d %.2e (|.| <= 1e-6), F - C %.7f (1 within 1e-5); index vs the double-precision "
      "equation: worst %.2e (<= 4e-7); vs the extension's rounded constants: %.2e of nF - nC (<= 1e-3); "
      "mutant with 1/lambda for 1/lambda^2: %.3f of nF - nC off at 400 nm\n",
      atD, fToC, worstIor, worstExtension, std::abs(mutantAt400));
  EXPECT_LE(std::abs(atD), 1e-6);
  EXPECT_NEAR(fToC, 1.0, 1e-5);
  EXPECT_LE(worstIor, 4e-7);
  EXPECT_LE(worstExtension, 1e-3);
  EXPECT_GT(std::abs(mutantAt400), 0.1) << "the mutant must differ where the test looks";
  EXPECT_EQ(DispersiveIor(1.5f, 0.0f, 400.0f), 1.5f) << "dispersion 0 is the plain index";
  EXPECT_EQ(DispersiveIor(1.01f, 1000.0f, 800.0f), 1.0f) << "the extension's clamp at 1";
}

// The table's bins, read as the renderers read them.
struct Bin {
  double start, end;
  glm::dvec3 weight;
};

std::vector<Bin> TableBins() {
  using namespace shader;  // VKPT_ALBEDO_PAIR's names
  std::vector<Bin> bins;
  for (uint32_t k = 0; k < kWavelengthBins; ++k) {
    const uint32_t pair = shader::kWavelengthOffset + 2u * k;
    const glm::vec2 a = VKPT_ALBEDO_PAIR(pair), b = VKPT_ALBEDO_PAIR(pair + 1u), next = VKPT_ALBEDO_PAIR(pair + 2u);
    bins.push_back({a.x, next.x, glm::dvec3(a.y, b.x, b.y)});
  }
  return bins;
}

// The largest amount by which the bins' weights, averaged over bins of equal
// probability, miss white.
double WhiteError(const std::vector<Bin>& bins) {
  glm::dvec3 mean(0.0);
  for (const Bin& b : bins) mean += b.weight / double(bins.size());
  return std::max({std::abs(mean.x - 1.0), std::abs(mean.y - 1.0), std::abs(mean.z - 1.0)});
}

TEST(Dispersion, WavelengthWeightsAverageToWhite) {
  const std::vector<Bin> bins = TableBins();
  double worstSum = 0.0;
  bool ordered = bins.front().start == 360.0 && bins.back().end == 830.0;
  for (const Bin& b : bins) {
    worstSum = std::max(worstSum, std::abs(b.weight.x + b.weight.y + b.weight.z - 3.0));
    ordered = ordered && b.end > b.start && std::min({b.weight.x, b.weight.y, b.weight.z}) >= 0.0;
  }
  // SampleWavelength over stratified u: each wavelength inside its bin, the weights
  // averaging to white.
  const int perBin = 16;
  glm::dvec3 sampled(0.0);
  int outside = 0;
  for (int i = 0; i < int(kWavelengthBins) * perBin; ++i) {
    const float u = (float(i) + 0.5f) / float(int(kWavelengthBins) * perBin);
    const glm::vec4 s = shader::SampleWavelength(u);
    const Bin& b = bins[size_t(i / perBin)];
    outside += s.x < b.start || s.x > b.end || glm::dvec3(s.y, s.z, s.w) != b.weight;
    sampled += glm::dvec3(s.y, s.z, s.w) / double(kWavelengthBins * perBin);
  }
  std::vector<Bin> mutant = bins;
  mutant.back().weight.x *= 1.05;  // one bin's red 5 % too strong
  std::printf(
      "%u bins from %.1f to %.1f nm: weights average to white within %.1e (<= 1e-6), sampled %.7f %.7f %.7f; "
      "bins' channels sum to 3 within %.1e (<= 2e-6); %d samples outside their bin; mutant (one bin 5 %% "
      "redder) %.1e\n",
      kWavelengthBins, bins.front().start, bins.back().end, WhiteError(bins), sampled.x, sampled.y, sampled.z, worstSum,
      outside, WhiteError(mutant));
  EXPECT_TRUE(ordered);
  EXPECT_LE(WhiteError(bins), 1e-6);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sampled[c], 1.0, 1e-6);
  EXPECT_LE(worstSum, 2e-6);
  EXPECT_EQ(outside, 0);
  EXPECT_GT(WhiteError(mutant), 1e-6);
}

// The bins against this test's own integration of the CIE table (midpoints of 0.01 nm
// over the whole range, of a thousandth of each bin within it, on its 1 nm interpolation): each bin holds 1/N of the
// mean normalised response, and its weight is N times the normalised response within it.
TEST(Dispersion, WavelengthBinsFollowTheCieTable) {
  VKPT_REQUIRE_CMF(cmf);
  std::array<std::vector<double>, 3> rgb;
  for (size_t i = 0; i < cmf.x.size(); ++i) {
    const glm::vec3 c = shader::XyzToRec709(glm::vec3(float(cmf.x[i]), float(cmf.y[i]), float(cmf.z[i])));
    for (int k = 0; k < 3; ++k) rgb[k].push_back(std::max(double(c[k]), 0.0));
  }
  auto at = [&](int c, double nm) {
    const double x = nm - cie::kFirstNm;
    const size_t i = std::min(size_t(x), rgb[c].size() - 2);
    return rgb[c][i] + (x - double(i)) * (rgb[c][i + 1] - rgb[c][i]);
  };
  const double step = 0.01;
  glm::dvec3 total(0.0);
  for (double nm = cie::kFirstNm + step / 2; nm < cie::kLastNm; nm += step)
    total += glm::dvec3(at(0, nm), at(1, nm), at(2, nm)) * step;
  double worstShare = 0.0, worstWeight = 0.0;
  for (const Bin& b : TableBins()) {
    glm::dvec3 inBin(0.0);
    const int steps = 1000;
    const double width = (b.end - b.start) / steps;
    for (int i = 0; i < steps; ++i) {
      const double nm = b.start + (i + 0.5) * width;
      inBin += glm::dvec3(at(0, nm), at(1, nm), at(2, nm)) * width / total;
    }
    const double n = kWavelengthBins;
    worstShare = std::max(worstShare, std::abs((inBin.x + inBin.y + inBin.z) / 3.0 * n - 1.0));
    const glm::dvec3 off = glm::abs(inBin * n - b.weight);
    worstWeight = std::max({worstWeight, off.x, off.y, off.z});
  }
  std::printf("CIE 1931 bins: each holds 1/%u of the response within %.1e (<= 2e-3), weights within %.1e (<= 2e-3)\n",
              kWavelengthBins, worstShare, worstWeight);
  EXPECT_LE(worstShare, 2e-3);
  EXPECT_LE(worstWeight, 2e-3);
}

// The image mean; `nonFinite` counts the channels that were not finite.
glm::dvec3 DispersiveFurnace(float roughness, test::PathVariantRenderer render, uint64_t* nonFinite) {
  Material glass = test::ClearGlass(glm::vec3(1.0f), glm::vec3(0.0f), 1.5f);
  glass.specular = 1.0f;
  glass.roughness = roughness;
  glass.dispersion = 5.0f;
  Scene s = test::SphereInFurnace(glass);
  RenderScene rs = PrepareRenderScene(s);
  RenderResult r = render(rs, test::SphereFurnaceParams(rs, s, 13));
  *nonFinite = r.nonFinite;
  return test::MeanAndError(r.image, glm::dvec3(1.0)).mean;
}

// Every wavelength keeps its energy in the sphere, so each channel returns 1 when the
// colour weights average to white — drawn once per path, however often it refracts.
TEST(Dispersion, DispersiveGlassSphereInAWhiteFurnaceReturnsOne) {
  uint64_t nonFinite = 0;
  for (float roughness : {0.0f, 0.3f}) {
    const glm::dvec3 mean = DispersiveFurnace(
        roughness, [](const RenderScene& rs, const shader::FrameParams& p) { return RenderCpu(rs, p); }, &nonFinite);
    EXPECT_EQ(nonFinite, 0u);
    std::printf("dispersive glass sphere (20/Vd = 5) furnace, roughness %.1f: %.4f %.4f %.4f (1 within 1 %%)\n",
                roughness, mean.x, mean.y, mean.z);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], 1.0, 0.01) << "roughness " << roughness << ", channel " << c;
  }
}

// The weight compounds over the path's crossings: far off, or beyond binary32.
TEST(Dispersion, MutantWeightingEveryVertexLeavesTheFurnace) {
  VKPT_REQUIRE_PATH_VARIANTS();
  uint64_t nonFinite = 0;
  const glm::dvec3 mutant = DispersiveFurnace(0.0f, test::RenderMutantWavelengthWeightEveryVertex, &nonFinite);
  const double off = std::max({std::abs(mutant.x - 1.0), std::abs(mutant.y - 1.0), std::abs(mutant.z - 1.0)});
  std::printf(
      "mutant weighting every dispersive vertex: %.3g %.3g %.3g, %llu channels not finite (must be > 5 %% off)\n",
      mutant.x, mutant.y, mutant.z, (unsigned long long)nonFinite);
  EXPECT_TRUE(!(off <= 0.05) || nonFinite > 0u);
}

// ---------------------------------------------------------------------------------------
// A prism seen through an orthographic camera looking down −z: rays enter its top face
// (z = 0) at normal incidence, leave through a face tilted by kApex, and fall on an
// emissive strip kScreen below. Each wavelength leaves at the angle Snell's law gives for
// its index, so the strip's image is spread into a spectrum across the columns. The
// glass reflects nothing (specular 0), so every path crosses both faces, and the
// expected colour of a column is the table's bins' weights times the share of each bin's
// wavelengths, and of the column's footprint, that reach the strip.

constexpr double kApex = M_PI / 6.0;  // the exit face's tilt
constexpr double kScreen = 4.0;       // the strip's depth below the top face
constexpr double kStripWidth = 0.1;
constexpr float kPrismIor = 1.5f, kPrismDispersion = 2.0f;

// Where a ray entering the top face at x meets the screen, for index n: affine in x.
// (Returns the coefficients m, b of X = m x + b.)
glm::dvec2 ScreenHit(double n) {
  const double t = std::tan(kApex);
  const glm::dvec2 normal(std::sin(kApex), -std::cos(kApex)), d(0.0, -1.0);  // (x, z)
  const double cosI = glm::dot(d, normal), eta = n;
  const double cosT = std::sqrt(1.0 - eta * eta * (1.0 - cosI * cosI));
  const glm::dvec2 out = eta * (d - cosI * normal) + cosT * normal;
  const double s = out.x / -out.y;  // the exit point is at z = −(1 − x) t
  return {1.0 + s * t, s * (kScreen - t)};
}

double StripCentre() { return ScreenHit(double(kPrismIor)).y; }  // where λd lands from x = 0

std::vector<SceneTriangle> PrismTriangles() {
  const double t = std::tan(kApex);
  const float y = 2.0f;
  const glm::vec3 p0(-1, 0, 0), p1(1, 0, 0), p2(-1, 0, float(-2.0 * t)), up(0, y, 0);
  const glm::vec3 centre = (p0 + p1 + p2) / 3.0f;
  std::vector<SceneTriangle> tris;
  auto add = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {  // wound to face away from the centre
    if (glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.0f - centre) < 0.0f) std::swap(b, c);
    tris.push_back({a, b, c, 0});
  };
  auto quad = [&](glm::vec3 a, glm::vec3 b) {  // the side from edge a–b, across y
    add(a - up, b - up, b + up);
    add(a - up, b + up, a + up);
  };
  quad(p0, p1);
  quad(p1, p2);
  quad(p2, p0);
  add(p0 - up, p1 - up, p2 - up);
  add(p0 + up, p1 + up, p2 + up);
  // The strip, facing the prism.
  const float x0 = float(StripCentre() - kStripWidth / 2), x1 = float(StripCentre() + kStripWidth / 2);
  const float z = float(-kScreen), h = 50.0f;
  tris.push_back({{x0, -h, z}, {x1, -h, z}, {x1, h, z}, 1});
  tris.push_back({{x0, -h, z}, {x1, h, z}, {x0, h, z}, 1});
  return tris;
}

Scene PrismScene() {
  Material glass = test::ClearGlass(glm::vec3(1.0f), glm::vec3(0.0f), kPrismIor);
  glass.dispersion = kPrismDispersion;
  Material strip{};
  strip.emission = glm::vec3(1.0f);
  Scene s = test::MakeScene(PrismTriangles(), {glass, strip});
  Camera cam = test::OrthographicAlongMinusZ(5.0f, 0.5f);
  cam.ymag = 0.5f / 8.0f;  // 64 × 8 pixels over x in [−0.5, 0.5]
  s.cameras.push_back(cam);
  return s;
}

constexpr uint32_t kPrismWidth = 64, kPrismHeight = 8;

shader::FrameParams PrismParams(const RenderScene& rs, const Scene& s) {
  shader::FrameParams p = MakeFrameParams(rs, s.cameras[0], kPrismWidth, kPrismHeight);
  p.seed = 17;
  p.sampleCount = 1024 / test::kSampleDivisor;
  p.maxDepth = 2;  // top face, exit face, strip
  p.rrDepth = 2;
  p.background = glm::vec3(0.0f);
  return p;
}

// The expected mean of column `column`, from the index `ior(nm)` and the bins `bins`.
using IorOf = std::function<double(double)>;
glm::dvec3 ExpectedColumn(uint32_t column, const std::vector<Bin>& bins, const IorOf& ior) {
  const double x0 = -0.5 + double(column) / kPrismWidth, x1 = x0 + 1.0 / kPrismWidth;
  const double a = StripCentre() - kStripWidth / 2, b = StripCentre() + kStripWidth / 2;
  glm::dvec3 sum(0.0);
  const int steps = 64;
  for (const Bin& bin : bins)
    for (int i = 0; i < steps; ++i) {
      const glm::dvec2 hit = ScreenHit(ior(bin.start + (bin.end - bin.start) * (i + 0.5) / steps));
      // The part of [x0, x1] whose X = m x + c falls on the strip.
      const double lo = std::max(x0, (a - hit.y) / hit.x), hi = std::min(x1, (b - hit.y) / hit.x);
      sum += bin.weight * (std::max(hi - lo, 0.0) / (x1 - x0) / steps / double(bins.size()));
    }
  return sum;
}

// Per channel, the light reaching the image (the mean over its columns) and its centroid
// in columns: a spectrum's colours sit where their wavelengths' deviations put them.
struct Spectrum {
  glm::dvec3 total{0.0}, centroid{0.0};
};

template <class ColumnMean>
Spectrum SpectrumOf(const ColumnMean& column) {
  Spectrum s;
  for (uint32_t x = 0; x < kPrismWidth; ++x) {
    const glm::dvec3 m = column(x);
    s.total += m / double(kPrismWidth);
    s.centroid += m * (double(x) + 0.5) / double(kPrismWidth);
  }
  s.centroid /= s.total;
  return s;
}

Spectrum ModelSpectrum(const std::vector<Bin>& bins, const IorOf& ior) {
  return SpectrumOf([&](uint32_t x) { return ExpectedColumn(x, bins, ior); });
}

// The largest difference of centroids, in columns, and of totals, relative.
glm::dvec2 Mismatch(const Spectrum& a, const Spectrum& b) {
  glm::dvec2 worst(0.0);
  for (int c = 0; c < 3; ++c)
    worst =
        glm::max(worst, glm::dvec2(std::abs(a.centroid[c] - b.centroid[c]), std::abs(a.total[c] / b.total[c] - 1.0)));
  return worst;
}

// The image against the bins and Snell's law with the Cauchy index. The glass's GGX lobe,
// however smooth (α = 1e-3), blurs each wavelength's image by about a column, so the
// comparison is of what blurring keeps: each channel's light and its centroid.
void ExpectSpectrumFollowsSnell(const Image& image, const char* backend) {
  const Spectrum rendered = SpectrumOf([&](uint32_t x) {
    glm::dvec3 m(0.0);
    for (uint32_t y = 0; y < kPrismHeight; ++y) m += glm::dvec3(image.At(x, y)) / double(kPrismHeight);
    return m;
  });
  const std::vector<Bin> bins = TableBins();
  std::vector<Bin> reversed = bins;  // red bent most, blue least
  for (size_t k = 0; k < bins.size(); ++k) reversed[k].weight = bins[bins.size() - 1 - k].weight;
  const Spectrum snell = ModelSpectrum(bins, [](double nm) { return CauchyIor(kPrismIor, kPrismDispersion, nm); });
  const Spectrum plain = ModelSpectrum(bins, [](double) { return double(kPrismIor); });  // no dispersion
  const Spectrum backwards =
      ModelSpectrum(reversed, [](double nm) { return CauchyIor(kPrismIor, kPrismDispersion, nm); });
  const glm::dvec2 off = Mismatch(rendered, snell), offPlain = Mismatch(rendered, plain),
                   offBackwards = Mismatch(rendered, backwards);
  std::printf(
      "%s prism (ior %.2f, 20/Vd %.1f): centroids R %.2f G %.2f B %.2f columns (Snell: %.2f %.2f %.2f), light "
      "%.4f %.4f %.4f (Snell: %.4f %.4f %.4f); worst %.2f columns (<= 0.25), %.2f %% (<= 2 %%); without "
      "dispersion %.2f columns, colours reversed %.2f (>= 3)\n",
      backend, kPrismIor, kPrismDispersion, rendered.centroid.x, rendered.centroid.y, rendered.centroid.z,
      snell.centroid.x, snell.centroid.y, snell.centroid.z, rendered.total.x, rendered.total.y, rendered.total.z,
      snell.total.x, snell.total.y, snell.total.z, off.x, 100.0 * off.y, offPlain.x, offBackwards.x);
  EXPECT_LE(off.x, 0.25);
  EXPECT_LE(off.y, 0.02);
  EXPECT_GE(offPlain.x, 3.0);
  EXPECT_GE(offBackwards.x, 3.0);
}

TEST(Dispersion, PrismSpreadsTheSpectrumAsSnellsLawSays) {
  Scene s = PrismScene();
  RenderScene rs = PrepareRenderScene(s);
  const shader::FrameParams p = PrismParams(rs, s);
  ASSERT_NEAR(p.tanHalfFovY * p.aspect, 0.5f, 1e-6f);
  ASSERT_EQ(p.right, glm::vec3(1.0f, 0.0f, 0.0f));
  RenderResult r = RenderCpu(rs, p);
  EXPECT_EQ(r.nonFinite, 0u);
  ExpectSpectrumFollowsSnell(r.image, "CPU");
}

class DispersionGpuTest : public test::ValidatedGpuTest {};

TEST_F(DispersionGpuTest, DispersivePrismMatchesSnellAndTheCpu) {
  Scene s = PrismScene();
  RenderScene rs = PrepareRenderScene(s);
  const shader::FrameParams p = PrismParams(rs, s);
  vk::GpuRenderer gpu(test::Gpu(), rs);
  RenderResult g = gpu.Render(p);
  EXPECT_EQ(g.nonFinite, 0u);
  ExpectSpectrumFollowsSnell(g.image, "GPU");
  ImageComparison c = CompareImages(RenderCpu(rs, p).image, g.image);
  std::printf("GPU prism vs CPU: %s\n", c.Summary().c_str());
  EXPECT_TRUE(c.lockstepAgree);
}

// The glass slab with a closed opaque box far off, and inside the box a triangle that no
// ray can reach: made dispersive, it turns on the GPU's dispersion (a specialization
// constant) and leaves every other path as it was, bit for bit.
Scene SlabWithHiddenTriangle(float dispersion) {
  Scene s = test::GlassSlabScene(test::ClearGlass(glm::vec3(1.0f, 0.9f, 0.7f), glm::vec3(0.1f, 0.5f, 1.5f), 1.5f));
  Material box{};
  box.baseColor = glm::vec3(0.5f);
  Material hidden = test::ClearGlass(glm::vec3(1.0f), glm::vec3(0.0f), 1.3f);
  hidden.dispersion = dispersion;
  s.materials.push_back(box);
  s.materials.push_back(hidden);
  s.materialNames.push_back("box");
  s.materialNames.push_back("hidden");
  const uint32_t boxMaterial = uint32_t(s.materials.size() - 2), hiddenMaterial = boxMaterial + 1;
  glm::vec3 c[8];
  for (int i = 0; i < 8; ++i) c[i] = glm::vec3(i & 1 ? 12 : 10, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    s.triangles.push_back({c[f[0]], c[f[1]], c[f[2]], boxMaterial});
    s.triangles.push_back({c[f[0]], c[f[2]], c[f[3]], boxMaterial});
  }
  s.triangles.push_back({{10.5f, -0.5f, 0.0f}, {11.5f, -0.5f, 0.0f}, {11.0f, 0.5f, 0.0f}, hiddenMaterial});
  for (const SceneTriangle& t : s.triangles) s.bounds.Extend(t.v0), s.bounds.Extend(t.v1), s.bounds.Extend(t.v2);
  return s;
}

TEST_F(DispersionGpuTest, DispersionUnseenLeavesTheImageBitIdentical) {
  VKPT_SKIP_UNDER_ADDRESS_SANITIZER("a bit-identity of two GPU renders, 8 s");
  Scene plain = SlabWithHiddenTriangle(0.0f), dispersive = SlabWithHiddenTriangle(1.0f);
  RenderScene rsPlain = PrepareRenderScene(plain), rsDispersive = PrepareRenderScene(dispersive);
  ASSERT_FALSE(UsesDispersion(rsPlain));
  ASSERT_TRUE(UsesDispersion(rsDispersive)) << "the test must switch the GPU's dispersion on";
  shader::FrameParams p = MakeFrameParams(rsPlain, plain.cameras[0], 48, 48);
  p.seed = 5;
  p.sampleCount = 16;
  p.maxDepth = 8;
  p.rrDepth = 4;
  p.background = glm::vec3(2.0f, 1.0f, 0.5f);
  vk::GpuRenderer gpuPlain(test::Gpu(), rsPlain), gpuDispersive(test::Gpu(), rsDispersive);
  const Image a = gpuPlain.Render(p).image, b = gpuDispersive.Render(p).image;
  const Image ca = RenderCpu(rsPlain, p).image, cb = RenderCpu(rsDispersive, p).image;
  int gpuDiffering = 0, cpuDiffering = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    gpuDiffering += a.pixels[i] != b.pixels[i];
    cpuDiffering += ca.pixels[i] != cb.pixels[i];
  }
  std::printf("an unreachable dispersive triangle: %d GPU and %d CPU pixels of %zu differ (must be 0)\n", gpuDiffering,
              cpuDiffering, a.pixels.size());
  EXPECT_EQ(gpuDiffering, 0);
  EXPECT_EQ(cpuDiffering, 0);
}

}  // namespace
}  // namespace vkpt::internal

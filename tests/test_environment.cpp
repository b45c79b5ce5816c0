// The environment map of shared/environment.h on the CPU: its orientation convention, and
// SampleEnvironment against EnvironmentPdf (χ², normalisation, the pdf each sample reports).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cpu/cpu_path.h"
#include "image/image_load.h"
#include "shared/rng.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

using namespace shader;

std::string EnvironmentFile(const std::string& name) { return test::SharedData("gltf-pbr/environments/" + name); }

// A RenderScene holding only an environment map, and frame constants for it.
struct EnvScene {
  RenderScene scene;
  FrameParams params{};
  EnvScene(uint32_t w, uint32_t h, const std::vector<glm::vec3>& radiance, float rotationDegrees = 0.0f) {
    scene.environment = BuildEnvironmentMap(w, h, radiance);
    SetEnvironmentParams(params, scene.environment, rotationDegrees, 1.0f);
  }
};

EnvScene LoadMap(const std::string& name, float rotationDegrees = 0.0f) {
  std::vector<std::string> warnings;
  Image image = ReadEnvironmentImage(
      EnvironmentFile(name), [](uint64_t, const std::string&) {}, &warnings);
  EXPECT_TRUE(warnings.empty());
  return EnvScene(image.width, image.height, image.pixels, rotationDegrees);
}

// One bright texel (value 100) at (col, row) of a black w × h map.
EnvScene OneTexel(uint32_t w, uint32_t h, uint32_t col, uint32_t row, float rotationDegrees = 0.0f) {
  std::vector<glm::vec3> radiance(size_t(w) * h, glm::vec3(0.0f));
  radiance[size_t(row) * w + col] = glm::vec3(100.0f);
  return EnvScene(w, h, radiance, rotationDegrees);
}

// A 93 × 45 map with what makes sampling hard: a sun 10⁵ times the sky, texel noise, and a
// black ground (rows 30 and below) whose cells must get no samples. The ground's top two
// rows are 10⁻⁸ dim, so that no sample lands in the black's neighbour cells, from which
// float rounding of u → direction → u could move it across the edge.
EnvScene SyntheticMap() {
  const uint32_t w = 93, h = 45;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> noise(0.0f, 1.0f);
  std::vector<glm::vec3> radiance(size_t(w) * h);
  for (uint32_t j = 0; j < h; ++j)
    for (uint32_t i = 0; i < w; ++i) {
      glm::vec3 sky = glm::vec3(0.3f, 0.5f, 1.0f) * (0.2f + noise(rng)) * (1.0f + float(j) / h);
      radiance[j * w + i] = j < 28 ? sky : j < 30 ? 1e-8f * sky : glm::vec3(0.0f);
    }
  for (uint32_t j = 20; j < 22; ++j)
    for (uint32_t i = 60; i < 62; ++i) radiance[j * w + i] = glm::vec3(1e5f, 8e4f, 5e4f);
  return EnvScene(w, h, radiance, 30.0f);
}

// The probability of each cell of a grid of bx × by texels in (u, v): the integral of
// EnvironmentPdf over each texel, where it is constant (pdf_uv = pdf_ω · 2π² sin θ).
std::vector<double> CellMass(const EnvScene& e, uint32_t bx, uint32_t by) {
  const uint32_t w = e.params.envWidth, h = e.params.envHeight, nx = w / bx;
  std::vector<double> mass(size_t(nx) * (h / by), 0.0);
  for (uint32_t j = 0; j < h; ++j)
    for (uint32_t i = 0; i < w; ++i) {
      double v = (j + 0.5) / h;
      vec3 dir = EnvUvToDirection(e.params, vec2(float((i + 0.5) / w), float(v)));
      double pdfUv = EnvironmentPdf(e.scene, e.params, dir) * 2.0 * M_PI * M_PI * std::sin(M_PI * v);
      mass[(j / by) * nx + i / bx] += pdfUv / (double(w) * h);
    }
  return mass;
}

// χ² of 10⁶ samples binned by (u, v) against CellMass; a sample in a cell of mass 0 fails.
void ExpectSamplesMatchPdf(const EnvScene& e, uint32_t bx, uint32_t by, const char* what) {
  const uint32_t kSamples = 1000000, w = e.params.envWidth, h = e.params.envHeight, nx = w / bx;
  const double alpha = test::SidakAlpha(0.01, 2);  // two maps
  std::vector<double> expected = CellMass(e, bx, by), observed(expected.size(), 0.0);
  for (double& m : expected) m *= kSamples;
  uint32_t inZeroCells = 0;
  for (uint32_t k = 0; k < kSamples; ++k) {
    vec4 r = Random4(11u, k, 0u, 0u);
    EnvSample s = SampleEnvironment(e.scene, e.params, vec2(r.x, r.y));
    ASSERT_GT(s.pdf, 0.0f) << "sample " << k;
    vec2 uv = EnvDirectionToUv(e.params, s.dir);
    uint32_t i = std::min(uint32_t(uv.x * w), w - 1), j = std::min(uint32_t(uv.y * h), h - 1);
    size_t cell = (j / by) * nx + i / bx;
    observed[cell] += 1.0;
    if (expected[cell] == 0.0) ++inZeroCells;
  }
  double stat;
  int dof;
  double p = test::ChiSquareTest(observed, expected, &stat, &dof);
  std::printf("%s: chi2 = %.1f, dof = %d, p = %.4f (alpha %.4f); samples in zero-pdf cells: %u\n", what, stat, dof, p,
              alpha, inZeroCells);
  EXPECT_GT(p, alpha);
  EXPECT_EQ(inZeroCells, 0u);
}

// ∫ pdf dω over the sphere by the midpoint rule, 2 × 2 points per texel.
double IntegratePdf(const EnvScene& e) {
  const uint32_t nu = 2 * e.params.envWidth, nv = 2 * e.params.envHeight;
  double sum = 0.0;
  for (uint32_t j = 0; j < nv; ++j) {
    double v = (j + 0.5) / nv;
    for (uint32_t i = 0; i < nu; ++i) {
      vec3 dir = EnvUvToDirection(e.params, vec2(float((i + 0.5) / nu), float(v)));
      sum += EnvironmentPdf(e.scene, e.params, dir) * 2.0 * M_PI * M_PI * std::sin(M_PI * v) / (double(nu) * nv);
    }
  }
  return sum;
}

// The pdf SampleEnvironment reports against EnvironmentPdf of its direction. A sample
// within float rounding of a cell edge may come back in the neighbouring cell, so a few
// (at most 1 in 1000) may differ.
void ExpectReportedPdfs(const EnvScene& e, const char* what) {
  const uint32_t kSamples = 100000;
  uint32_t differ = 0;
  for (uint32_t k = 0; k < kSamples; ++k) {
    vec4 r = Random4(12u, k, 0u, 0u);
    EnvSample s = SampleEnvironment(e.scene, e.params, vec2(r.z, r.w));
    float pdf = EnvironmentPdf(e.scene, e.params, s.dir);
    if (!(std::abs(pdf - s.pdf) <= 1e-3f * s.pdf)) ++differ;
    ASSERT_NEAR(glm::length(s.dir), 1.0f, 1e-5f);
    glm::vec3 L = EnvRadiance(e.scene, e.params, s.dir);
    ASSERT_EQ(s.radiance, L);
  }
  std::printf("%s: %u of %u sampled pdfs differ from EnvironmentPdf by more than 1e-3\n", what, differ, kSamples);
  EXPECT_LE(differ, kSamples / 1000);
}

TEST(Environment, ConventionPlacesTheCentreAtMinusZ) {
  EnvScene e = OneTexel(9, 5, 4, 2);  // the centre texel: u = v = 0.5
  vec2 uv = EnvDirectionToUv(e.params, vec3(0, 0, -1));
  EXPECT_NEAR(uv.x, 0.5f, 1e-6f);
  EXPECT_NEAR(uv.y, 0.5f, 1e-6f);
  EXPECT_NEAR(EnvDirectionToUv(e.params, vec3(1, 0, 0)).x, 0.75f, 1e-6f);
  EXPECT_NEAR(EnvDirectionToUv(e.params, vec3(-1, 0, 0)).x, 0.25f, 1e-6f);
  EXPECT_NEAR(EnvDirectionToUv(e.params, vec3(0, 1, 0)).y, 0.0f, 1e-6f);
  EXPECT_NEAR(EnvDirectionToUv(e.params, vec3(0, -1, 0)).y, 1.0f, 1e-6f);
  EXPECT_NEAR(EnvRadiance(e.scene, e.params, vec3(0, 0, -1)).x, 100.0f, 1e-3f);
  for (vec3 d : {vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 0, 1), vec3(0, 1, 0), vec3(0, -1, 0)})
    EXPECT_EQ(EnvRadiance(e.scene, e.params, d).x, 0.0f) << d.x << " " << d.y << " " << d.z;
}

TEST(Environment, ThreeQuartersOfTheWidthIsPlusXAndTheTopRowPlusY) {
  EnvScene e = OneTexel(6, 3, 4, 1);  // u = 4.5 / 6 = 0.75, v = 0.5
  EXPECT_NEAR(EnvRadiance(e.scene, e.params, vec3(1, 0, 0)).x, 100.0f, 1e-3f);
  EXPECT_EQ(EnvRadiance(e.scene, e.params, vec3(-1, 0, 0)).x, 0.0f);
  std::vector<glm::vec3> top(6 * 3, glm::vec3(0.0f));
  for (int i = 0; i < 6; ++i) top[i] = glm::vec3(5.0f);
  EnvScene sky(6, 3, top);
  EXPECT_NEAR(EnvRadiance(sky.scene, sky.params, vec3(0, 1, 0)).x, 5.0f, 1e-5f);
  EXPECT_EQ(EnvRadiance(sky.scene, sky.params, vec3(0, -1, 0)).x, 0.0f);
}

// --env-rotation 90: counter-clockwise seen from above (from +Y), so what faced −Z faces −X.
TEST(Environment, RotationTurnsCounterClockwiseSeenFromAbove) {
  EnvScene e = OneTexel(9, 5, 4, 2, 90.0f);
  EXPECT_NEAR(EnvRadiance(e.scene, e.params, vec3(-1, 0, 0)).x, 100.0f, 1e-2f);
  EXPECT_NEAR(EnvRadiance(e.scene, e.params, vec3(0, 0, -1)).x, 0.0f, 1e-3f);
  vec3 d = EnvUvToDirection(e.params, vec2(0.5f, 0.5f));
  EXPECT_NEAR(d.x, -1.0f, 1e-6f);
  EXPECT_NEAR(d.z, 0.0f, 1e-6f);
  // Round trip through a turned map, away from the seam and the poles.
  EnvScene turned = OneTexel(9, 5, 0, 0, 30.0f);
  for (vec2 uv : {vec2(0.1f, 0.2f), vec2(0.6f, 0.5f), vec2(0.95f, 0.9f)}) {
    vec2 back = EnvDirectionToUv(turned.params, EnvUvToDirection(turned.params, uv));
    EXPECT_NEAR(back.x, uv.x, 1e-5f);
    EXPECT_NEAR(back.y, uv.y, 1e-5f);
  }
}

TEST(Environment, BilinearLookupWrapsInUAndScalesByIntensity) {
  EnvScene e = OneTexel(8, 4, 0, 1);  // column 0: its left half blends with column 7
  e.params.envIntensity = 2.0f;
  // u = 0 lies halfway between the centres of columns 7 and 0; v at row 1's centre.
  vec3 dir = EnvUvToDirection(e.params, vec2(0.0f, 1.5f / 4.0f));
  EXPECT_NEAR(EnvRadiance(e.scene, e.params, dir).x, 100.0f, 1e-3f);
}

TEST(Environment, NoMapMeansTheBackgroundAndNoSamples) {
  RenderScene scene;
  FrameParams p{};
  p.background = vec3(0.25f, 0.5f, 1.0f);
  EXPECT_EQ(EnvRadiance(scene, p, vec3(0, 1, 0)), p.background);
  EXPECT_EQ(EnvironmentPdf(scene, p, vec3(0, 1, 0)), 0.0f);
  EXPECT_EQ(SampleEnvironment(scene, p, vec2(0.5f)).pdf, 0.0f);
}

TEST(Environment, SamplesMatchThePdfOnVeniceSunset) {
  VKPT_REQUIRE_SHARED_DATA();
  ExpectSamplesMatchPdf(LoadMap("venice_sunset_1k.hdr"), 16, 16, "venice_sunset_1k (64 x 32 cells)");
}

TEST(Environment, SamplesMatchThePdfOnASyntheticMap) {
  ExpectSamplesMatchPdf(SyntheticMap(), 1, 1, "synthetic 93 x 45 (a cell per texel)");
}

TEST(Environment, PdfIntegratesToOne) {
  VKPT_REQUIRE_SHARED_DATA();
  for (const char* name : {"venice_sunset_1k.hdr", "potsdamer_platz_1k.hdr"}) {
    double integral = IntegratePdf(LoadMap(name, 30.0f));
    std::printf("%s: integral of the pdf over the sphere %.6f\n", name, integral);
    EXPECT_NEAR(integral, 1.0, 1e-3) << name;
  }
}

TEST(Environment, PdfIntegratesToOneOnASyntheticMap) { EXPECT_NEAR(IntegratePdf(SyntheticMap()), 1.0, 1e-3); }

TEST(Environment, SampledPdfEqualsEnvironmentPdf) {
  VKPT_REQUIRE_SHARED_DATA();
  ExpectReportedPdfs(LoadMap("venice_sunset_1k.hdr", 45.0f), "venice_sunset_1k");
}

TEST(Environment, SampledPdfEqualsEnvironmentPdfOnASyntheticMap) { ExpectReportedPdfs(SyntheticMap(), "synthetic"); }

// Every direction the bilinear lookup gives radiance has a pdf: next to a lone bright
// texel too, where the texel's own weight would leave its neighbours' cells at 0.
TEST(Environment, EveryLitDirectionHasAPdf) {
  EnvScene e = OneTexel(16, 8, 5, 3);
  for (uint32_t j = 0; j < 64; ++j)
    for (uint32_t i = 0; i < 128; ++i) {
      vec3 dir = EnvUvToDirection(e.params, vec2((i + 0.5f) / 128, (j + 0.5f) / 64));
      if (EnvRadiance(e.scene, e.params, dir).x > 0.0f) {
        ASSERT_GT(EnvironmentPdf(e.scene, e.params, dir), 0.0f);
      }
    }
}

}  // namespace
}  // namespace vkpt::internal

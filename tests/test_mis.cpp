// Multiple importance sampling: an area light over a glossy metal plane, and one behind a
// rough thin wall, direct light only, estimated three ways — light sampling alone, BSDF sampling alone (test-only
// builds of the shared estimator, path_variants.h) and the product's MIS. All three are unbiased estimates of the same
// image, so their means must agree (z-tests) at every roughness; a wrong MIS weight or a wrong BSDF pdf makes them
// disagree, and the mutant tests prove that the test sees it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cpu/path_tracer.h"
#include "gltf_builder.h"
#include "path_variants.h"
#include "png_writer.h"
#include "render/render_scene.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

using namespace test;
using shader::FrameParams;

const double kRoughness[] = {0.1, 0.3, 0.7};

// A 6 × 6 plane y = 0 of material `planeMaterial` (glTF JSON) and a one-sided emissive quad
// (1 × 1, radiance 4) at height `lightY`, facing the plane; the camera (Frame) sees the
// plane, not the light.
GltfBuilder PlaneAndQuadLightModel(const std::string& planeMaterial, float lightY,
                                   const std::vector<std::string>& extensions) {
  GltfBuilder b;
  int plane = b.Positions({{-3, 0, -3}, {-3, 0, 3}, {3, 0, 3}, {3, 0, -3}});
  int light =
      b.Positions({{-0.5f, lightY, -1.5f}, {0.5f, lightY, -1.5f}, {0.5f, lightY, -0.5f}, {-0.5f, lightY, -0.5f}});
  b.materials = {planeMaterial, R"({"pbrMetallicRoughness":{"baseColorFactor":[0,0,0,1]},"emissiveFactor":[1,1,1],)"
                                R"("extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":4}}})"};
  b.Mesh(plane, b.Indices({0, 1, 2, 0, 2, 3}), 0);
  // Wound to face down (−y) from above the plane, up from below it.
  b.Mesh(light,
         b.Indices(lightY > 0.0f ? std::vector<uint32_t>{0, 1, 2, 0, 2, 3} : std::vector<uint32_t>{0, 2, 1, 0, 3, 2}),
         1);
  b.Node(R"({"mesh":0})");
  b.Node(R"({"mesh":1})");
  b.scenes = {R"({"nodes":[0,1]})"};
  b.extensionsUsed = extensions;
  b.extensionsUsed.push_back("KHR_materials_emissive_strength");
  return b;
}

Scene PlaneAndQuadLight(const std::string& planeMaterial, float lightY, const std::vector<std::string>& extensions) {
  return Load(PlaneAndQuadLightModel(planeMaterial, lightY, extensions));
}

// A metal plane (baseColor copper-like, metallic 1, the given roughness) under the light
// at height 1.5, whose reflection the camera sees.
Scene GlossyPlaneUnderAreaLight(double roughness) {
  return PlaneAndQuadLight(R"({"pbrMetallicRoughness":{"baseColorFactor":[0.95,0.64,0.54,1],"metallicFactor":1,)"
                           R"("roughnessFactor":)" +
                               Num(roughness) + "}}",
                           1.5f, {});
}

// The light 1.5 below a rough transmissive thin wall (white, the given roughness) that
// hides it from the camera: all the light the camera sees came through the wall, sampled
// through it by light sampling and found by transmitted BSDF samples.
Scene LightBehindThinWall(double roughness) {
  return PlaneAndQuadLight(
      R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1],"metallicFactor":0,"roughnessFactor":)" + Num(roughness) +
          R"(},"extensions":{"KHR_materials_transmission":{"transmissionFactor":1}}})",
      -1.5f, {"KHR_materials_transmission"});
}

// The light 1.5 below a diffusely transmitting thin wall (a rough red dielectric passing
// the given share of its diffuse base through as pale blue): light sampling through the
// wall and the transmitted cosine lobe must agree.
Scene LightBehindDiffuseWall(double share) {
  return PlaneAndQuadLight(
      R"({"pbrMetallicRoughness":{"baseColorFactor":[0.9,0.3,0.2,1],"metallicFactor":0,"roughnessFactor":0.4},)"
      R"("extensions":{"KHR_materials_diffuse_transmission":{"diffuseTransmissionFactor":)" +
          Num(share) + R"(,"diffuseTransmissionColorFactor":[0.6,0.8,1]}}})",
      -1.5f, {"KHR_materials_diffuse_transmission"});
}

// The glossy plane under a light whose emission an emissive texture paints: 4 × 4 texels
// of different colours and brightness, NEAREST, over the quad. Light sampling
// must read the texture at the point it picks as a hit there would.
Scene GlossyPlaneUnderTexturedLight(double roughness) {
  GltfBuilder b = PlaneAndQuadLightModel(R"({"pbrMetallicRoughness":{"baseColorFactor":[0.95,0.64,0.54,1],)"
                                         R"("metallicFactor":1,"roughnessFactor":)" +
                                             Num(roughness) + "}}",
                                         1.5f, {});
  std::vector<uint8_t> texels;
  for (int k = 0; k < 16; ++k)
    texels.insert(texels.end(), {uint8_t(k * 17), uint8_t(255 - k * 13), uint8_t(k * 40 % 256)});
  const int uv = b.Accessor(b.View(Bytes(std::vector<float>{0, 0, 1, 0, 1, 1, 0, 1})), kFloat, 4, "VEC2");
  b.meshes[1].insert(b.meshes[1].find("\"POSITION\""), "\"TEXCOORD_0\":" + std::to_string(uv) + ",");
  const std::vector<unsigned char> png = MakePng(4, 4, 8, 2, texels);
  b.images.push_back(R"({"mimeType":"image/png","bufferView":)" +
                     std::to_string(b.View(std::string(png.begin(), png.end()))) + "}");
  b.textures.push_back(R"({"source":0,"sampler":0})");
  b.extraTopLevel += R"(,"samplers":[{"magFilter":9728,"minFilter":9728}])";
  b.materials[1].insert(b.materials[1].find("\"emissiveFactor\""), R"("emissiveTexture":{"index":0},)");
  return Load(b);
}

// 48 × 32, `spp` samples, one bounce (the light reflected once), black background.
FrameParams Frame(const RenderScene& rs, uint32_t spp, uint32_t seed) {
  Camera cam;
  cam.position = {0.0f, 1.2f, 2.0f};
  cam.forward = glm::normalize(glm::vec3(0.0f, 0.0f, -0.6f) - cam.position);
  cam.right = glm::normalize(glm::cross(cam.forward, glm::vec3(0, 1, 0)));
  cam.up = glm::cross(cam.right, cam.forward);
  cam.yfov = 0.7f;
  FrameParams p = MakeFrameParams(rs, cam, 48, 32);
  p.seed = seed;
  p.sampleCount = spp;
  p.maxDepth = 1;
  p.rrDepth = 1000;
  p.background = glm::vec3(0.0f);
  return p;
}

RenderResult RenderProduct(const RenderScene& rs, const FrameParams& p) { return RenderCpu(rs, p); }

struct Estimators {
  PathVariantRenderer lightOnly = RenderMisLightOnly;
  PathVariantRenderer bsdfOnly = RenderMisBsdfOnly;
  PathVariantRenderer mis = RenderProduct;
  const char* name = "product MIS";
};

// Family of 3 roughnesses × 3 pairs × 3 channels; a test fails when |z| exceeds the
// Šidák-corrected critical value for family α = 0.01 AND the means differ by more than
// 0.5 % (float summation over ~10⁵ samples is far below that).
constexpr int kTests = 27;
constexpr double kMargin = 0.005;

double CriticalZ() {
  const double alpha = SidakAlpha(0.01, kTests);
  double lo = 0.0, hi = 10.0;  // NormalSurvivalTwoSided(z) = alpha, by bisection
  for (int i = 0; i < 100; ++i) {
    double mid = 0.5 * (lo + hi);
    (NormalSurvivalTwoSided(mid) > alpha ? lo : hi) = mid;
  }
  return hi;
}

struct Verdict {
  int failures = 0;     // tests significant beyond the margin
  double worstZ = 0.0;  // largest |z| over all tests
};

// Renders the scene at each roughness with the three estimators (independent seeds) and
// z-tests every pair's image means, per channel.
Verdict CompareEstimators(const Estimators& e, uint32_t spp, Scene (*makeScene)(double) = GlossyPlaneUnderAreaLight) {
  const double zCrit = CriticalZ();
  Verdict v;
  for (double roughness : kRoughness) {
    Scene scene = makeScene(roughness);
    RenderScene rs = PrepareRenderScene(scene);
    EXPECT_EQ(rs.lights.size(), 2u);  // the quad's two triangles
    struct Run {
      const char* name;
      ZTest t;
    } runs[3];
    const PathVariantRenderer renderers[3] = {e.lightOnly, e.bsdfOnly, e.mis};
    const char* names[3] = {"light only", "BSDF only", e.name};
    for (int k = 0; k < 3; ++k) {
      RenderResult r = renderers[k](rs, Frame(rs, spp, uint32_t(k + 1)));
      EXPECT_EQ(r.nonFinite, 0u) << names[k];
      runs[k] = {names[k], MeanAndError(r.image, glm::dvec3(0.0))};
    }
    for (auto [a, b] : {std::pair{0, 2}, {1, 2}, {0, 1}}) {
      const ZTest &ta = runs[a].t, &tb = runs[b].t;
      for (int c = 0; c < 3; ++c) {
        double diff = ta.mean[c] - tb.mean[c];
        double z = diff / std::sqrt(ta.stderr_[c] * ta.stderr_[c] + tb.stderr_[c] * tb.stderr_[c]);
        double rel = std::abs(diff) / std::max(ta.mean[c], tb.mean[c]);
        bool fail = std::abs(z) > zCrit && rel > kMargin;
        v.failures += fail;
        v.worstZ = std::max(v.worstZ, std::abs(z));
        std::printf(
            "roughness %.1f, %s vs %s, channel %d: %.5f (±%.5f) vs %.5f (±%.5f), z %6.2f, rel diff %.4f "
            "(fails if |z| > %.2f and rel > %.3f) %s\n",
            roughness, runs[a].name, runs[b].name, c, ta.mean[c], ta.stderr_[c], tb.mean[c], tb.stderr_[c], z, rel,
            zCrit, kMargin, fail ? "FAIL" : "ok");
      }
    }
  }
  std::printf("[%s] %d of %d tests fail; worst |z| %.2f\n", e.name, v.failures, kTests, v.worstZ);
  return v;
}

// The agreement test takes 512 samples per pixel (light sampling alone is the noisiest at
// roughness 0.1; a quarter under sanitizers); the mutants are caught with a quarter of
// that, and a bias only stands out more with more samples.
constexpr uint32_t kSpp = 512 / kSampleDivisor, kMutantSpp = 128;

// Every test renders the estimator's variants (path_variants.h).
class Mis : public ::testing::Test {
 protected:
  void SetUp() override { VKPT_REQUIRE_PATH_VARIANTS(); }
};

TEST_F(Mis, LightBsdfAndMisEstimatesAgreeAtThreeRoughnesses) {
  Verdict v = CompareEstimators(Estimators{}, kSpp);
  EXPECT_EQ(v.failures, 0);
}

// Light sampled through the surface (shadow ray from its far side, BSDF transmission
// lobe evaluated and its pdf in the MIS weight) against transmitted BSDF samples that hit
// the light.
TEST_F(Mis, LightThroughAThinWallAgreesAtThreeRoughnesses) {
  Verdict v = CompareEstimators(Estimators{}, kSpp, LightBehindThinWall);
  EXPECT_EQ(v.failures, 0);
}

// kRoughness doubles as the share transmitted: 0.1, 0.3 and 0.7.
TEST_F(Mis, DiffuseTransmissionAgreesAtThreeShares) {
  Verdict v = CompareEstimators(Estimators{}, kSpp, LightBehindDiffuseWall);
  EXPECT_EQ(v.failures, 0);
}

// Light sampling reads the emissive texture where it samples the light (the emission of
// the sampled point), as BSDF sampling reads it where its ray hits.
// A quarter of kSpp: the estimators differ here only in where they read the texture, and
// the mutant below is caught with |z| > 100 at half of this.
TEST_F(Mis, TexturedLightAgreesAtThreeRoughnesses) {
  Verdict v = CompareEstimators(Estimators{}, kMutantSpp, GlossyPlaneUnderTexturedLight);
  EXPECT_EQ(v.failures, 0);
}

// Estimators whose light samples (light sampling alone, and MIS) come from `mutant`.
Estimators WithLightSampleMutant(PathVariantRenderer mutant, const char* name) {
  Estimators e;
  e.lightOnly = mutant;
  e.mis = mutant;
  e.name = name;
  return e;
}

// Light samples that take the emissive factor for the emission, texture ignored.
TEST_F(Mis, MutantLightSampleWithoutTextureIsCaught) {
  const Estimators e =
      WithLightSampleMutant(RenderMutantLightSampleWithoutTexture, "mutant: light samples ignore the emissive texture");
  EXPECT_GT(CompareEstimators(e, kMutantSpp / 2, GlossyPlaneUnderTexturedLight).failures, 0);
}

// A clear-coated plane (coat roughness as given, over a rough red dielectric) under a
// clear-coated light: the coat lobe's pdf, and the coat dimming the emission where light
// sampling picks a point as where a ray hits, must give the same image every way.
Scene CoatedPlaneUnderCoatedLight(double roughness) {
  GltfBuilder b = PlaneAndQuadLightModel(
      R"({"pbrMetallicRoughness":{"baseColorFactor":[0.8,0.3,0.2,1],"metallicFactor":0,"roughnessFactor":0.5},)"
      R"("extensions":{"KHR_materials_clearcoat":{"clearcoatFactor":1,"clearcoatRoughnessFactor":)" +
          Num(roughness) + "}}}",
      1.5f, {"KHR_materials_clearcoat"});
  b.materials[1].insert(b.materials[1].find("\"KHR_materials_emissive_strength\""),
                        R"("KHR_materials_clearcoat":{"clearcoatFactor":1},)");
  return Load(b);
}

TEST_F(Mis, ClearcoatAgreesAtThreeRoughnesses) {
  Verdict v = CompareEstimators(Estimators{}, kSpp, CoatedPlaneUnderCoatedLight);
  EXPECT_EQ(v.failures, 0);
}

// A sheened plane (sheen roughness as given, over a rough red dielectric) under the light:
// the sheen lobe's pdf and its base scaling must give the same image every way.
Scene SheenedPlaneUnderLight(double roughness) {
  return Load(PlaneAndQuadLightModel(
      R"({"pbrMetallicRoughness":{"baseColorFactor":[0.8,0.3,0.2,1],"metallicFactor":0,"roughnessFactor":0.5},)"
      R"("extensions":{"KHR_materials_sheen":{"sheenColorFactor":[1,0.9,0.7],"sheenRoughnessFactor":)" +
          Num(roughness) + "}}}",
      1.5f, {"KHR_materials_sheen"}));
}

TEST_F(Mis, SheenAgreesAtThreeRoughnesses) {
  Verdict v = CompareEstimators(Estimators{}, kSpp, SheenedPlaneUnderLight);
  EXPECT_EQ(v.failures, 0);
}

// Light samples that take the coated emitter's emission undimmed.
TEST_F(Mis, MutantLightSampleWithoutCoatIsCaught) {
  const Estimators e = WithLightSampleMutant(RenderMutantLightSampleWithoutCoat,
                                             "mutant: light samples ignore the emitter's clear coat");
  EXPECT_GT(CompareEstimators(e, kMutantSpp, CoatedPlaneUnderCoatedLight).failures, 0);
}

// Both strategies counted in full: the light's reflection twice.
TEST_F(Mis, MutantWeightOneIsCaught) {
  Estimators e;
  e.mis = RenderMutantMisWeightOne;
  e.name = "mutant: MIS weights 1 (double counting)";
  EXPECT_GT(CompareEstimators(e, kMutantSpp).failures, 0);
}

// The light sample weighted by the BSDF sample's weight: the weights no longer sum to one.
TEST_F(Mis, MutantSwappedPdfsIsCaught) {
  Estimators e;
  e.mis = RenderMutantMisSwappedPdfs;
  e.name = "mutant: light sample's power heuristic with swapped pdfs";
  EXPECT_GT(CompareEstimators(e, kMutantSpp).failures, 0);
}

// GgxReflectionPdf without 1/(4 ωo·h), in every estimator that uses it (light sampling
// alone evaluates the BSDF, never its pdf, and stays correct).
TEST_F(Mis, MutantMissingJacobianIsCaught) {
  Estimators e;
  e.bsdfOnly = RenderMutantNoJacobianBsdfOnly;
  e.mis = RenderMutantNoJacobian;
  e.name = "mutant: GGX pdf without 1/(4 wo.h)";
  EXPECT_GT(CompareEstimators(e, kMutantSpp).failures, 0);
}

}  // namespace
}  // namespace vkpt::internal

// The CPU reference estimator against analytic answers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include <glm/gtc/epsilon.hpp>

#include "cpu/path_tracer.h"
#include "gltf/gltf_loader.h"
#include "render/render_scene.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

shader::FrameParams Params(const Scene& scene, const RenderScene& rs, uint32_t w, uint32_t h, uint32_t spp, uint32_t maxDepth,
                           uint32_t rrDepth, uint32_t seed = 1) {
  shader::FrameParams p = MakeFrameParams(rs, scene.cameras.empty() ? DefaultCamera(scene.bounds) : scene.cameras[0], w, h);
  p.seed = seed;
  p.sampleCount = spp;
  p.maxDepth = maxDepth;
  p.rrDepth = rrDepth;
  return p;
}

using test::Agrees;
using test::FurnaceExpected;
using test::MeanAndError;

// The film both renderers resolve their sums through: samples 1, 2, 6 give the mean 3
// and the sample variance ((−2)² + (−1)² + 3²) / 2 = 7, so the mean's variance is 7/3.
TEST(Render, FilmGivesMeanAndVarianceOfTheMean) {
  Film film(3, 1);
  film.SetPixel(0, {glm::dvec3(1 + 2 + 6, 0, 3), glm::dvec3(1 + 4 + 36, 0, 3), 3});  // G: 0, 0, 0; B: 1, 1, 1
  film.SetPixel(1, {glm::dvec3(3), glm::dvec3(3), 3});                               // 1, 1, 1: no spread
  film.SetPixel(2, {glm::dvec3(8), glm::dvec3(32), 2});                              // two samples of 4: no spread
  Image image = film.TakeImage();
  ASSERT_EQ(image.variance.size(), 3u);
  EXPECT_FLOAT_EQ(image.pixels[0].x, 3.0f);
  EXPECT_FLOAT_EQ(image.variance[0].x, 7.0f / 3.0f);
  EXPECT_EQ(image.pixels[0].y, 0.0f);
  EXPECT_EQ(image.variance[0].y, 0.0f);
  EXPECT_FLOAT_EQ(image.pixels[0].z, 1.0f);
  EXPECT_EQ(image.variance[0].z, 0.0f);  // samples 1, 1, 1
  EXPECT_EQ(image.pixels[1], glm::vec3(1.0f));
  EXPECT_EQ(image.variance[1], glm::vec3(0.0f));
  EXPECT_EQ(image.pixels[2], glm::vec3(4.0f));  // each pixel by its own count (adaptive sampling)
  EXPECT_EQ(image.variance[2], glm::vec3(0.0f));

  Film single(2, 1);  // one sample: no variance estimate, 0; none: black
  single.SetPixel(0, {glm::dvec3(5.0), glm::dvec3(25.0), 1});
  single.SetPixel(1, {glm::dvec3(5.0), glm::dvec3(25.0), 0});
  Image one = single.TakeImage();
  EXPECT_EQ(one.pixels[0], glm::vec3(5.0f));
  EXPECT_EQ(one.variance[0], glm::vec3(0.0f));
  EXPECT_EQ(one.pixels[1], glm::vec3(0.0f));
}

TEST(Render, FurnaceMatchesClosedForm) {
  Scene scene = LoadGltf(test::SourcePath("scenes/furnace.gltf"));
  RenderScene rs = PrepareRenderScene(scene);
  RenderResult r = RenderCpu(rs, Params(scene, rs, 32, 32, 256, 200, 3));
  EXPECT_EQ(r.nonFinite, 0u);
  glm::dvec3 expected = FurnaceExpected(scene, 200);
  EXPECT_NEAR(expected.y, 1.0, 1e-9);  // the scene's own statement: (0.5/0.7, 1, 2.5)
  EXPECT_TRUE(Agrees(MeanAndError(r.image, expected), expected, 1e-3, "furnace"));
}

TEST(Render, FurnaceHonoursDepthCapWithoutRoulette) {
  // D = 2 and roulette off: exactly Le(1 + ρ + ρ²) — pins down what --max-depth counts.
  Scene scene = LoadGltf(test::SourcePath("scenes/furnace.gltf"));
  RenderScene rs = PrepareRenderScene(scene);
  RenderResult r = RenderCpu(rs, Params(scene, rs, 16, 16, 64, 2, 1000));
  glm::dvec3 expected = FurnaceExpected(scene, 2);
  EXPECT_TRUE(Agrees(MeanAndError(r.image, expected), expected, 1e-3, "furnace D=2"));
  RenderResult r0 = RenderCpu(rs, Params(scene, rs, 8, 8, 4, 0, 1000));
  for (const glm::vec3& p : r0.image.pixels) EXPECT_EQ(p, scene.materials[0].emission) << "D = 0: emission only";
}

// Proof of teeth: the same test must reject an estimator that is 2 % off. Rendering
// with albedo scaled by 0.98 while expecting the true answer must fail the check.
TEST(Render, FurnaceTestDetectsATwoPercentError) {
  VKPT_SKIP_UNDER_ADDRESS_SANITIZER("a mutant's rejection, 8 s");
  Scene scene = LoadGltf(test::SourcePath("scenes/furnace.gltf"));
  glm::dvec3 expected = FurnaceExpected(scene, 200);
  scene.materials[0].baseColor *= 0.98f;
  RenderScene rs = PrepareRenderScene(scene);
  RenderResult r = RenderCpu(rs, Params(scene, rs, 32, 32, 256, 200, 3));
  EXPECT_FALSE(Agrees(MeanAndError(r.image, expected), expected, 1e-3, "furnace with wrong albedo (must fail)"));
}

TEST(Render, ConvexObjectInUniformEnvironmentReflectsRhoTimesE) {
  // White-furnace test of the environment: a point on a convex object sees the
  // environment E over its whole hemisphere, so it reflects exactly ρE — zero variance.
  std::vector<SceneTriangle> tris;
  glm::vec3 c[8];
  for (int i = 0; i < 8; ++i) c[i] = glm::vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  int faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  for (auto& f : faces) {
    tris.push_back({c[f[0]], c[f[1]], c[f[2]], 0});
    tris.push_back({c[f[0]], c[f[2]], c[f[3]], 0});
  }
  Material m{};
  m.baseColor = glm::vec3(0.25f, 0.5f, 0.75f);
  Scene scene = test::MakeScene(tris, {m});
  RenderScene rs = PrepareRenderScene(scene);
  shader::FrameParams p = Params(scene, rs, 24, 24, 8, 5, 3);
  p.background = glm::vec3(2.0f, 1.0f, 0.5f);
  RenderResult r = RenderCpu(rs, p);
  glm::vec3 onObject = m.baseColor * p.background;
  int object = 0, env = 0;
  for (const glm::vec3& px : r.image.pixels) {
    if (glm::all(glm::epsilonEqual(px, onObject, 1e-5f))) ++object;
    else if (glm::all(glm::epsilonEqual(px, p.background, 1e-5f))) ++env;
    else if (glm::all(glm::lessThanEqual(glm::min(onObject, p.background), px + 1e-5f)) &&
             glm::all(glm::lessThanEqual(px, glm::max(onObject, p.background) + 1e-5f))) ++env;  // silhouette mix
    else ADD_FAILURE() << "pixel (" << px.x << ", " << px.y << ", " << px.z << ") is neither ρE nor E";
  }
  std::printf("object pixels %d, environment/edge pixels %d\n", object, env);
  EXPECT_GT(object, 100);
  EXPECT_GT(env, 100);
}

TEST(Render, CornellBoxLooksLikeTheCornellBox) {
  Scene scene = LoadGltf(test::SourcePath("scenes/cornell.gltf"));
  RenderScene rs = PrepareRenderScene(scene);
  ASSERT_EQ(rs.lights.size(), 2u);
  EXPECT_NEAR(rs.lights[0].extent + rs.lights[1].extent, 13650.0, 1e-2);
  RenderResult r = RenderCpu(rs, Params(scene, rs, 64, 64, 16, 32, 3));
  EXPECT_EQ(r.nonFinite, 0u);
  // Mean of the left and right image columns: red wall left, green wall right.
  glm::dvec3 left(0.0), right(0.0);
  float brightest = 0.0f;
  for (uint32_t y = 0; y < 64; ++y) {
    left += glm::dvec3(r.image.At(2, y));
    right += glm::dvec3(r.image.At(61, y));
    for (uint32_t x = 0; x < 64; ++x) brightest = std::max(brightest, r.image.At(x, y).x);
  }
  std::printf("left column mean (%.3f %.3f %.3f), right (%.3f %.3f %.3f), brightest %.2f\n", left.x / 64, left.y / 64,
              left.z / 64, right.x / 64, right.y / 64, right.z / 64, brightest);
  EXPECT_GT(left.x, 2.0 * left.y) << "red wall on the left";
  EXPECT_GT(right.y, 1.5 * right.x) << "green wall on the right";
  EXPECT_GE(brightest, 47.8f) << "the light itself is visible with radiance ≥ Le";
}

TEST(Render, ImageIsIdenticalForAnyThreadCount) {
  Scene scene = LoadGltf(test::SourcePath("scenes/cornell.gltf"));
  RenderScene rs = PrepareRenderScene(scene);
  shader::FrameParams p = Params(scene, rs, 40, 30, 4, 32, 3, 77);
  CpuRenderOptions one, three;
  one.threads = 1;
  three.threads = 3;
  Image a = RenderCpu(rs, p, one).image;
  Image b = RenderCpu(rs, p, three).image;
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  EXPECT_EQ(0, std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)));
  p.seed = 78;
  Image c = RenderCpu(rs, p, one).image;
  EXPECT_NE(0, std::memcmp(a.pixels.data(), c.pixels.data(), a.pixels.size() * sizeof(glm::vec3)));
}

// Every sample of `rs`, and its rays, bit for bit from the general estimator and from
// `estimator`, one compiled for fewer features.
using Estimator = glm::vec3 (*)(const RenderScene&, const shader::FrameParams&, uint32_t, uint32_t, uint32_t,
                                SampleStats&);
void ExpectSameSamplesAsTheGeneralEstimator(const RenderScene& rs, const shader::FrameParams& p, Estimator estimator) {
  SampleStats general, specialized;
  for (uint32_t y = 0; y < p.height; ++y)
    for (uint32_t x = 0; x < p.width; ++x)
      for (uint32_t s = 0; s < p.sampleCount; ++s) {
        const glm::vec3 a = SampleRadiance(rs, p, x, y, s, general);
        const glm::vec3 b = estimator(rs, p, x, y, s, specialized);
        ASSERT_EQ(0, std::memcmp(&a, &b, sizeof a)) << "pixel " << x << "," << y << " sample " << s;
      }
  EXPECT_EQ(general.rays, specialized.rays);
}

// The Cornell box is a simple scene: the CPU renders it with SampleRadianceSimple, which
// must give every sample bit for bit as the general estimator does.
TEST(Render, SimpleSceneEstimatorEqualsTheGeneralOne) {
  Scene scene = LoadGltf(test::SourcePath("scenes/cornell.gltf"));
  RenderScene rs = PrepareRenderScene(scene);
  shader::FrameParams p = Params(scene, rs, 24, 24, 8, 32, 3, 5);
  ASSERT_TRUE(IsSimpleScene(rs, p));
  ASSERT_FALSE(rs.shading.empty());
  ExpectSameSamplesAsTheGeneralEstimator(rs, p, SampleRadianceSimple);
  // What makes a scene not simple: a glossy material on a triangle, vertex normals, a
  // punctual light, an environment map, vertex colours, a volume. An unused glossy material does not.
  RenderScene glossy = rs;
  glossy.materials.back().metallic = 1.0f;  // the loader's default material, unused
  EXPECT_TRUE(IsSimpleScene(glossy, p));
  glossy.materials[glossy.triangles[0].material].metallic = 1.0f;
  EXPECT_FALSE(IsSimpleScene(glossy, p));
  RenderScene smooth = rs;
  smooth.shading[0].flags |= shader::kShadingHasNormals;
  EXPECT_FALSE(IsSimpleScene(smooth, p));
  RenderScene point = rs;
  point.lights[0].type = shader::kLightPoint;
  EXPECT_FALSE(IsSimpleScene(point, p));
  shader::FrameParams env = p;
  env.envWidth = 1;
  EXPECT_FALSE(IsSimpleScene(rs, env));
  RenderScene volume = rs;
  volume.materials[volume.triangles[0].material].flags |= shader::kMaterialVolume;
  EXPECT_FALSE(IsSimpleScene(volume, p));
  RenderScene colored = rs;
  colored.vertexColors.resize(rs.shading.size());
  EXPECT_FALSE(IsSimpleScene(colored, p));
}

// A scene whose materials use none of the layered extensions is rendered by
// SampleRadianceCore, which must give every sample as the general estimator does: the
// Cornell box made of metals, rough dielectrics and glass volumes, and a textured quad.
TEST(Render, CoreSceneEstimatorEqualsTheGeneralOne) {
  Scene scene = LoadGltf(test::SourcePath("scenes/cornell.gltf"));
  for (size_t m = 0; m < scene.materials.size(); ++m) {
    Material& mat = scene.materials[m];
    mat.roughness = 0.2f + 0.15f * float(m % 4);
    mat.metallic = m % 3 == 2 ? 1.0f : 0.0f;
    mat.transmission = 1.0f;
    mat.volume = true;
    mat.attenuation = glm::vec3(0.2f, 0.4f, 0.8f);
  }
  RenderScene rs = PrepareRenderScene(scene);
  shader::FrameParams p = Params(scene, rs, 24, 24, 8, 32, 3, 5);
  ASSERT_FALSE(IsSimpleScene(rs, p));
  ASSERT_TRUE(IsCoreScene(rs));
  ExpectSameSamplesAsTheGeneralEstimator(rs, p, SampleRadianceCore);
  Scene quad = test::TexturedQuadScene();
  RenderScene rsQuad = PrepareRenderScene(quad);
  ASSERT_TRUE(IsCoreScene(rsQuad));
  ExpectSameSamplesAsTheGeneralEstimator(rsQuad, test::TestFrame(rsQuad, quad, 16, 4, 7, 4), SampleRadianceCore);
  // Any layered extension on a triangle's material makes the scene not core; on an unused
  // material it does not.
  using Edit = void (*)(shader::Material&);
  const Edit kLayers[] = {[](shader::Material& m) { m.clearcoat = 1.0f; },
                          [](shader::Material& m) { m.sheenColor = glm::vec3(0.5f); },
                          [](shader::Material& m) { m.diffuseTransmission = 0.5f; },
                          [](shader::Material& m) { m.iridescence = 1.0f; },
                          [](shader::Material& m) { m.anisotropy = 0.5f; },
                          [](shader::Material& m) { m.dispersion = 1.0f; }};
  for (Edit edit : kLayers) {
    RenderScene layered = rs;
    edit(layered.materials.back());  // the loader's default material, unused
    EXPECT_TRUE(IsCoreScene(layered));
    edit(layered.materials[layered.triangles[0].material]);
    EXPECT_FALSE(IsCoreScene(layered));
  }
}

}  // namespace
}  // namespace vkpt::internal

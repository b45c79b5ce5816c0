// Lights against answers known in closed form, on both backends (the estimator is shared):
// KHR_lights_punctual point, spot and directional lights over a Lambert plane, where one
// sample per pixel is exact (delta lights, one light, no bounce), and a constant
// environment map against the same constant --background, which must agree statistically.
// Deliberately wrong lights (test-only CPU builds, path_variants.h) must fail the closed
// forms, or the closed forms would guard nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "cpu/path_tracer.h"
#include "gltf_builder.h"
#include "gpu_test.h"
#include "image/image_compare.h"
#include "image/image_load.h"
#include "path_variants.h"
#include "render/light_table.h"
#include "render/render_scene.h"
#include "shared/rng.h"
#include "test_util.h"
#include "vk/vk_renderer.h"

namespace vkpt::internal {
namespace {

using namespace test;
using shader::FrameParams;

// Every test renders on the GPU too and ends by asserting the validation layer was silent.
class LightTransport : public test::ValidatedGpuTest {};

// ---------------------------------------------------------------------------------------
// Punctual lights over a Lambert plane

const glm::dvec3 kRho(0.8, 0.5, 0.25);  // the plane's albedo
constexpr double kHalfView = 1.5;       // the camera sees the square [−1.5, 1.5]² of the plane

// The plane y = 0 (front +Y, 8 × 8) of albedo kRho, pure Lambert (KHR_materials_specular
// factor 0, as scenes/cornell.gltf), and one KHR_lights_punctual light `light` on a node
// with `nodeFields`. Nothing else: with --max-depth 1 the plane reflects the light once.
Scene PlaneWithLight(const std::string& light, const std::string& nodeFields) {
  GltfBuilder b;
  const float s = 4.0f;
  int positions = b.Positions({{-s, 0, -s}, {-s, 0, s}, {s, 0, s}, {s, 0, -s}});
  int indices = b.Indices({0, 1, 2, 0, 2, 3});
  b.materials.push_back(R"({"pbrMetallicRoughness":{"baseColorFactor":[)" + Num(kRho.x) + "," + Num(kRho.y) + "," +
                        Num(kRho.z) +
                        R"(,1],"metallicFactor":0},"extensions":{"KHR_materials_specular":{"specularFactor":0}}})");
  b.Mesh(positions, indices, 0);
  b.Node(R"({"mesh":0})");
  b.Node(R"({"extensions":{"KHR_lights_punctual":{"light":0}})" + nodeFields + "}");
  b.scenes = {R"({"nodes":[0,1]})"};
  b.extensionsUsed = {"KHR_lights_punctual", "KHR_materials_specular"};
  b.extraTopLevel = R"(,"extensions":{"KHR_lights_punctual":{"lights":[)" + light + "]}}";
  Scene scene = Load(b);
  EXPECT_EQ(scene.lights.size(), 1u);
  EXPECT_TRUE(scene.ignoredFeatures.empty()) << ::testing::PrintToString(scene.ignoredFeatures);
  return scene;
}

// An orthographic camera straight above the plane (looking down −Y, image right +X, image
// up −Z), one sample per pixel, one bounce, black background.
FrameParams LookingDown(const RenderScene& rs, uint32_t size) {
  Camera cam;
  cam.orthographic = true;
  cam.position = {0.0f, 2.0f, 0.0f};
  cam.forward = {0.0f, -1.0f, 0.0f};
  cam.up = {0.0f, 0.0f, -1.0f};
  cam.right = {1.0f, 0.0f, 0.0f};
  cam.ymag = cam.xmag = float(kHalfView);
  FrameParams p = MakeFrameParams(rs, cam, size, size);
  p.seed = 5;
  p.sampleCount = 1;
  p.maxDepth = 1;
  p.rrDepth = 1000;
  p.background = glm::vec3(0.0f);
  return p;
}

// The point of the plane that the single sample of pixel (px, py) sees: the camera's jitter
// for sample 0 (the shared RNG, bit-identical on both backends) through the orthographic
// projection of GenerateCameraRay, in double precision.
glm::dvec3 SeenPoint(const FrameParams& p, uint32_t px, uint32_t py) {
  shader::vec2 j = shader::Sample2D(p.seed, py * p.width + px, p.sampleBegin, shader::kGroupCamera);
  double sx = 2.0 * (px + double(j.x)) / p.width - 1.0;
  double sy = 1.0 - 2.0 * (py + double(j.y)) / p.height;
  return {sx * kHalfView * p.aspect, 0.0, -sy * kHalfView};  // right = +X, up = −Z
}

// The KHR_lights_punctual spec's smooth range window and its spot cone attenuation
// (written out here from the spec, independently of lights.h).
double RangeWindow(double range, double dist) {
  if (range <= 0.0) return 1.0;
  return std::clamp(1.0 - std::pow(dist / range, 4.0), 0.0, 1.0);
}
double SpotAttenuation(glm::dvec3 spotDir, glm::dvec3 lightToPoint, double inner, double outer) {
  double cd = glm::dot(spotDir, glm::normalize(lightToPoint));
  double scale = 1.0 / std::max(0.001, std::cos(inner) - std::cos(outer));
  double offset = -std::cos(outer) * scale;
  double a = std::clamp(cd * scale + offset, 0.0, 1.0);
  return a * a;
}

// Lambert plane y = 0 under a point light of radiant intensity I at P: ρ/π · I cos θ / r².
glm::dvec3 PointRadiance(glm::dvec3 I, glm::dvec3 P, glm::dvec3 q) {
  glm::dvec3 d = P - q;
  double r = glm::length(d);
  return kRho / M_PI * I * (d.y / r) / (r * r);
}

struct ProbeStats {
  double maxRelError = 0.0;   // over channels whose expected value is above 1 % of the peak
  double maxDarkError = 0.0;  // |value − expected| / peak over the others (0 expected included)
  int lit = 0, dark = 0;      // probes with an expected red channel > 0, = 0
  int failures = 0;           // channels outside the tolerance
  std::string firstFailures;  // the first five of them, one a line
};

// Every pixel of `img` (one sample each) against `expected` at the point it sees: within
// 1e-4 relative + 1e-6 of the image's peak (float rounding; the range window and the
// cone's falloff amplify it near their edges, where the absolute term takes over).
ProbeStats CheckProbes(const Image& img, const FrameParams& p, const std::function<glm::dvec3(glm::dvec3)>& expected,
                       const char* what) {
  const double kRel = 1e-4, kAbs = 1e-6;
  ProbeStats st;
  double peak = 0.0;
  std::vector<glm::dvec3> want(img.pixels.size());
  for (uint32_t py = 0; py < p.height; ++py)
    for (uint32_t px = 0; px < p.width; ++px) {
      glm::dvec3 e = expected(SeenPoint(p, px, py));
      want[py * p.width + px] = e;
      peak = std::max({peak, e.x, e.y, e.z});
    }
  std::ostringstream firstFailures;
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    const glm::dvec3 e = want[i], v(img.pixels[i]);
    for (int c = 0; c < 3; ++c) {
      const double err = std::abs(v[c] - e[c]);
      if (e[c] > 1e-2 * peak) st.maxRelError = std::max(st.maxRelError, err / e[c]);
      else st.maxDarkError = std::max(st.maxDarkError, err / peak);
      if (!(err <= kRel * e[c] + kAbs * peak) && ++st.failures <= 5)
        firstFailures << what << ": pixel " << i % p.width << ", " << i / p.width << " channel " << c << ": " << v[c]
                      << ", expected " << e[c] << "\n";
    }
    (e.x > 0.0 ? st.lit : st.dark)++;
  }
  std::printf(
      "%s: %d lit and %d dark probes; |value - expected| <= %.0e expected + %.0e peak: max relative error "
      "%.2e where expected > 1 %% of the peak, max error / peak elsewhere %.2e; %d failures\n",
      what, st.lit, st.dark, kRel, kAbs, st.maxRelError, st.maxDarkError, st.failures);
  st.firstFailures = firstFailures.str();
  return st;
}

// A punctual light over the plane: the scene, the closed form every probe must match, and
// the fewest lit and dark probes (per image) that make it a test of what it is named for.
struct AnalyticCase {
  const char* name;
  Scene scene;
  std::function<glm::dvec3(glm::dvec3)> expected;
  int minLit, minDark;
};

AnalyticCase PointLight() {
  // color × intensity = (1, 0.5, 0.25) × 20 cd → I = (20, 10, 5) W/sr.
  const glm::dvec3 P(0.3, 0.8, -0.2), I(20.0, 10.0, 5.0);
  return {"point light: rho/pi I cos/r^2",
          PlaneWithLight(R"({"type":"point","color":[1,0.5,0.25],"intensity":20})", R"(,"translation":[0.3,0.8,-0.2])"),
          [=](glm::dvec3 q) { return PointRadiance(I, P, q); }, 1024, 0};
}

AnalyticCase PointLightWithRange() {
  // range 1.6 at height 0.8: the window cuts the light off ~1.39 from its foot point.
  const glm::dvec3 P(-0.4, 0.8, 0.3), I(7.0);
  return {"point light with range 1.6",
          PlaneWithLight(R"({"type":"point","intensity":7,"range":1.6})", R"(,"translation":[-0.4,0.8,0.3])"),
          [=](glm::dvec3 q) { return PointRadiance(I, P, q) * RangeWindow(1.6, glm::length(P - q)); }, 300, 100};
}

// Pointing straight down (node −Z turned −90° about X) from 1 above (0.2, 0, 0.1): the
// inner cone (0.3 rad) reaches 0.31 from the foot point, the outer (0.6 rad) 0.68.
const glm::dvec3 kSpotPosition(0.2, 1.0, 0.1), kSpotDirection(0.0, -1.0, 0.0);
constexpr double kSpotInner = 0.3, kSpotOuter = 0.6;

AnalyticCase SpotLight() {
  const double h = std::sqrt(0.5);
  const glm::dvec3 I(4.0, 6.0, 8.0);
  return {
      "spot light: inner 0.3, outer 0.6 rad",
      PlaneWithLight(
          R"({"type":"spot","color":[0.5,0.75,1],"intensity":8,"spot":{"innerConeAngle":0.3,"outerConeAngle":0.6}})",
          R"(,"translation":[0.2,1,0.1],"rotation":[)" + Num(-h) + ",0,0," + Num(h) + "]"),
      [=](glm::dvec3 q) {
        return PointRadiance(I, kSpotPosition, q) *
               SpotAttenuation(kSpotDirection, q - kSpotPosition, kSpotInner, kSpotOuter);
      },
      100, 500};
}

AnalyticCase DirectionalLight() {
  // Node −Z turned −60° about X: the light travels along (0, −sin 60°, −cos 60°), so
  // cos θ = sin 60° on the plane; E = (0.5, 1, 1) × 3 lux, 1:1 to irradiance.
  const double a = -M_PI / 6.0;  // half the angle
  const glm::dvec3 E(1.5, 3.0, 3.0);
  return {"directional light: rho/pi E cos",
          PlaneWithLight(R"({"type":"directional","color":[0.5,1,1],"intensity":3})",
                         R"(,"rotation":[)" + Num(std::sin(a)) + ",0,0," + Num(std::cos(a)) + "]"),
          [=](glm::dvec3) { return kRho / M_PI * E * std::sin(M_PI / 3.0); }, 1024, 0};
}

// One sample per pixel of a 32 × 32 view of the plane on each backend, every pixel a probe.
void ExpectAnalytic(const AnalyticCase& c) {
  RenderScene rs = PrepareRenderScene(c.scene);
  ASSERT_EQ(rs.lights.size(), 1u);
  FrameParams p = LookingDown(rs, 32);
  RenderResult cpu = RenderCpu(rs, p);
  vk::GpuRenderer gpu(Gpu(), rs);
  RenderResult g = gpu.Render(p);
  EXPECT_EQ(cpu.nonFinite + g.nonFinite, 0u);
  for (const auto& [img, backend] : {std::pair<const Image*, const char*>{&cpu.image, "CPU"}, {&g.image, "GPU"}}) {
    std::string what = std::string(c.name) + ", " + backend;
    ProbeStats st = CheckProbes(*img, p, c.expected, what.c_str());
    EXPECT_EQ(st.failures, 0) << st.firstFailures;
    EXPECT_GE(st.lit, c.minLit) << what;
    EXPECT_GE(st.dark, c.minDark) << what;
  }
}

TEST_F(LightTransport, PointLightOverLambertPlane) { ExpectAnalytic(PointLight()); }

TEST_F(LightTransport, PointLightRangeWindow) { ExpectAnalytic(PointLightWithRange()); }

TEST_F(LightTransport, SpotLightCone) {
  AnalyticCase c = SpotLight();
  int inside = 0, between = 0;
  c.expected = [&, closedForm = c.expected](glm::dvec3 q) {
    double angle = std::acos(glm::dot(kSpotDirection, glm::normalize(q - kSpotPosition)));
    inside += angle < kSpotInner;
    between += angle > kSpotInner && angle < kSpotOuter;
    return closedForm(q);
  };
  ExpectAnalytic(c);
  std::printf("probes per backend: %d inside the inner cone, %d between the cones\n", inside / 2, between / 2);
  EXPECT_GE(inside / 2, 20);
  EXPECT_GE(between / 2, 60);
}

TEST_F(LightTransport, DirectionalLightOverLambertPlane) { ExpectAnalytic(DirectionalLight()); }

class LightTransportMutants : public ::testing::Test {
 protected:
  void SetUp() override { VKPT_REQUIRE_PATH_VARIANTS(); }
};

// A mutant of lights.h (path_variants.h) rendered on the CPU as ExpectAnalytic renders:
// the case's closed form must reject it.
void ExpectMutantRejected(const AnalyticCase& c, PathVariantRenderer mutant, const char* mutantName) {
  RenderScene rs = PrepareRenderScene(c.scene);
  FrameParams p = LookingDown(rs, 32);
  RenderResult r = mutant(rs, p);
  EXPECT_EQ(r.nonFinite, 0u);
  std::string what = std::string(c.name) + ", CPU, mutant: " + mutantName;
  ProbeStats st = CheckProbes(r.image, p, c.expected, what.c_str());
  std::printf("%s", st.firstFailures.c_str());
  EXPECT_GT(st.failures, 0) << what << " passes";
}

TEST_F(LightTransportMutants, SpotFalloffNotSquaredIsRejected) {
  ExpectMutantRejected(SpotLight(), RenderMutantSpotFalloffLinear, "cone falloff linear, not squared");
}

TEST_F(LightTransportMutants, SquaredRangeWindowIsRejected) {
  ExpectMutantRejected(PointLightWithRange(), RenderMutantRangeWindowSquared, "range window squared");
}

TEST_F(LightTransportMutants, PointLightWithoutInverseSquareIsRejected) {
  ExpectMutantRejected(PointLight(), RenderMutantPointNoInverseSquare, "no 1/r^2");
}

TEST_F(LightTransportMutants, DirectionalLightWithExtraCosineIsRejected) {
  ExpectMutantRejected(DirectionalLight(), RenderMutantDirectionalExtraCosine, "E cos, then cos again");
}

// ---------------------------------------------------------------------------------------
// A constant environment map against the same constant background

const glm::vec3 kSky(0.5f, 1.0f, 2.0f);  // exact in RGBE: mantissas 32, 64, 128, exponent 130

// A w × h Radiance file of flat (not run-length encoded) RGBE texels, all `rgbe`.
std::string ConstantHdr(int w, int h, const std::string& rgbe) {
  std::string s = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(h) + " +X " + std::to_string(w) + "\n";
  for (int i = 0; i < w * h; ++i) s += rgbe;
  return s;
}

// A Lambert ground (6 × 6) with a unit box standing on it, both pure Lambert: the ground
// next to the box sees less sky and the two inter-reflect, so the answer is not the
// closed form ρE of a convex object.
Scene GroundAndBox() {
  GltfBuilder b;
  int ground = b.Positions({{-3, 0, -3}, {-3, 0, 3}, {3, 0, 3}, {3, 0, -3}});
  std::vector<glm::vec3> c;
  for (int i = 0; i < 8; ++i) c.push_back({i & 1 ? 0.5f : -0.5f, i & 2 ? 1.0f : 0.0f, i & 4 ? 0.5f : -0.5f});
  std::vector<uint32_t> box;
  for (auto f :
       {std::array<uint32_t, 4>{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}})
    for (uint32_t k : {0, 1, 2, 0, 2, 3}) box.push_back(f[k]);
  const std::string lambert = R"(,"metallicFactor":0},"extensions":{"KHR_materials_specular":{"specularFactor":0}}})";
  b.materials = {R"({"pbrMetallicRoughness":{"baseColorFactor":[0.7,0.7,0.7,1])" + lambert,
                 R"({"pbrMetallicRoughness":{"baseColorFactor":[0.2,0.5,0.8,1])" + lambert};
  b.Mesh(ground, b.Indices({0, 1, 2, 0, 2, 3}), 0);
  b.Mesh(b.Positions(c), b.Indices(box), 1);
  b.Node(R"({"mesh":0})");
  b.Node(R"({"mesh":1})");
  b.scenes = {R"({"nodes":[0,1]})"};
  b.extensionsUsed = {"KHR_materials_specular"};
  return Load(b);
}

Camera BoxCamera() {
  Camera cam;
  cam.position = {0.4f, 2.0f, 4.0f};
  cam.forward = glm::normalize(glm::vec3(0.0f, 0.4f, 0.0f) - cam.position);
  cam.right = glm::normalize(glm::cross(cam.forward, glm::vec3(0, 1, 0)));
  cam.up = glm::cross(cam.right, cam.forward);
  cam.yfov = 0.8f;
  return cam;
}

// Renders `rs` on the CPU or the GPU: 48 × 48, 64 spp, at most 6 bounces.
RenderResult RenderOn(bool gpu, const RenderScene& rs, FrameParams p) {
  p.sampleCount = 64;
  p.maxDepth = 6;
  p.rrDepth = 3;
  if (!gpu) return RenderCpu(rs, p);
  vk::GpuRenderer renderer(Gpu(), rs);
  return renderer.Render(p);
}

// The environment map in `file`, set up as vkpt --env FILE --env-intensity X
// --env-rotation 30 does (host/app/prepare.cpp): a light of the table, and the frame's map.
RenderResult RenderWithMap(bool gpu, const Scene& scene, const std::string& file, float intensity, uint32_t seed) {
  RenderScene rs = PrepareRenderScene(scene);
  std::vector<std::string> warnings;
  Image map = ReadEnvironmentImage(
      file, [](uint64_t, const std::string&) {}, &warnings);
  EXPECT_TRUE(warnings.empty());
  rs.environment = BuildEnvironmentMap(map.width, map.height, map.pixels);
  AddEnvironmentLight(rs, intensity);
  EXPECT_EQ(rs.lights.size(), 1u) << "the map is the only light";
  FrameParams p = MakeFrameParams(rs, BoxCamera(), 48, 48);
  SetEnvironmentParams(p, rs.environment, 30.0f, intensity);
  p.seed = seed;
  return RenderOn(gpu, rs, p);
}

// Welch z of the two image means, per channel (figures for the report; the verdict is
// CompareImages' region tests).
void PrintMeanZ(const Image& a, const Image& b, const char* what) {
  ZTest ta = MeanAndError(a, glm::dvec3(0.0)), tb = MeanAndError(b, glm::dvec3(0.0));
  glm::dvec3 z = (ta.mean - tb.mean) / glm::sqrt(ta.stderr_ * ta.stderr_ + tb.stderr_ * tb.stderr_);
  std::printf("%s: image means (%.5f %.5f %.5f) vs (%.5f %.5f %.5f), z (%.2f %.2f %.2f)\n", what, ta.mean.x, ta.mean.y,
              ta.mean.z, tb.mean.x, tb.mean.y, tb.mean.z, z.x, z.y, z.z);
}

// --background c against a constant map of radiance c: as .hdr at intensity 1, and as
// .exr holding c/4 at --env-intensity 4. The background is not a light (BSDF sampling
// alone finds it); the map is sampled by MIS with the BSDF: the same expectation.
TEST_F(LightTransport, ConstantEnvironmentEqualsBackground) {
  VKPT_SKIP_UNDER_ADDRESS_SANITIZER("four statistics on both backends, 20 s");
  const std::string dir = FreshTempDirectory("env-constant");
  const std::string hdr = dir + "/sky.hdr", exr = dir + "/quarter.exr";
  std::ofstream(hdr, std::ios::binary) << ConstantHdr(6, 3, std::string("\x20\x40\x80\x82", 4));
  Image quarter(8, 4);
  for (glm::vec3& t : quarter.pixels) t = kSky * 0.25f;
  WriteImage(quarter, exr);

  Scene scene = GroundAndBox();
  RenderScene plain = PrepareRenderScene(scene);
  ASSERT_TRUE(plain.lights.empty());
  FrameParams p = MakeFrameParams(plain, BoxCamera(), 48, 48);
  p.background = kSky;
  p.seed = 1;
  for (bool gpu : {false, true}) {
    const char* backend = gpu ? "GPU" : "CPU";
    RenderResult background = RenderOn(gpu, plain, p);
    struct {
      const std::string& file;
      float intensity;
      const char* name;
    } maps[] = {{hdr, 1.0f, "constant .hdr, intensity 1"}, {exr, 4.0f, "constant/4 .exr, --env-intensity 4"}};
    for (const auto& m : maps) {
      RenderResult env = RenderWithMap(gpu, scene, m.file, m.intensity, 2);
      EXPECT_EQ(background.nonFinite + env.nonFinite, 0u);
      ImageComparison c = CompareImages(background.image, env.image);
      std::string what = std::string(backend) + ": --background vs " + m.name;
      std::printf("[%s]\n%s\n", what.c_str(), c.Summary().c_str());
      std::printf("worst |z| %.2f, smallest p %.3g vs Sidak threshold %.3g (%d tests), margin %.2f\n", c.worstZ,
                  c.worstP, c.alphaPerTest, c.tests, c.options.margin);
      PrintMeanZ(background.image, env.image, what.c_str());
      EXPECT_TRUE(c.usedVariances);
      EXPECT_TRUE(c.statisticallyAgree) << what;
    }
  }
}

}  // namespace
}  // namespace vkpt::internal

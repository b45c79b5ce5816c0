// AOVs (shaders/shared/aov.h, session/aov.h): exact albedo, normals, depth and position on
// an axis-aligned box, the environment's albedo, the specular walk, agreement of the CPU
// and the GPU, the spp AOV under adaptive sampling, and the files vkpt writes.
#include <gtest/gtest.h>
#include <tinyexr.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "cpu/path_tracer.h"
#include "gltf/gltf_loader.h"
#include "gpu_test.h"
#include "render/render_scene.h"
#include "scene/scene_ids.h"
#include "session/aov.h"
#include "session/noise_estimate.h"
#include "test_util.h"
#include "util/error.h"
#include "vk/vk_renderer.h"

namespace vkpt::internal {
namespace {

constexpr glm::vec3 kEye(3.0f, 2.5f, 4.0f);
constexpr glm::vec3 kBackground(0.25f, 0.5f, 2.0f);

// The box [−1, 1]³ with a Lambertian material of its own per face (face k's normal is
// axis k / 2, positive for even k), seen from kEye by a perspective camera aimed at its
// centre, so that the faces +X, +Y and +Z fill most of the image. `front`, if given,
// replaces the material of the +Z face.
Scene BoxScene(const Material* front = nullptr) {
  std::vector<Material> materials;
  for (int k = 0; k < 6; ++k) {
    Material m{};
    m.baseColor = glm::vec3(0.1f + 0.15f * k, 0.8f - 0.1f * k, k % 2 ? 0.3f : 0.6f);
    materials.push_back(m);
  }
  if (front) materials[4] = *front;
  std::vector<SceneTriangle> tris;
  for (int k = 0; k < 6; ++k) {
    const int axis = k / 2;
    const float side = k % 2 ? -1.0f : 1.0f;
    glm::vec3 n(0.0f), u(0.0f), v(0.0f);
    n[axis] = side;
    u[(axis + 1) % 3] = 1.0f;
    v[(axis + 2) % 3] = 1.0f;
    if (side < 0.0f) std::swap(u, v);  // counter-clockwise seen from outside
    const glm::vec3 a = n - u - v, b = n + u - v, c = n + u + v, d = n - u + v;
    tris.push_back({a, b, c, uint32_t(k)});
    tris.push_back({a, c, d, uint32_t(k)});
  }
  Scene s = test::MakeScene(tris, materials);
  Camera cam;
  cam.position = kEye;
  cam.forward = glm::normalize(-kEye);
  cam.right = glm::normalize(glm::cross(cam.forward, glm::vec3(0, 1, 0)));
  cam.up = glm::cross(cam.right, cam.forward);
  cam.yfov = 0.6f;
  s.cameras.push_back(cam);
  return s;
}

struct Box {
  Scene scene;
  RenderScene cpu, gpu;
  explicit Box(const Material* front = nullptr)
      : scene(BoxScene(front)), cpu(PrepareRenderScene(scene)), gpu(PrepareRenderScene(scene, GpuLayout(), false)) {}
  static BvhBuildOptions GpuLayout() {
    BvhBuildOptions o;
    o.directionCopies = true;
    return o;
  }
  shader::FrameParams Frame(uint32_t size) const {
    shader::FrameParams p = test::TestFrame(cpu, scene, size, 1, 7, 8);
    p.background = kBackground;
    return p;
  }
};

// Which face a normal is exactly (k as in BoxScene), or −1.
int ExactFace(glm::dvec3 n) {
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {1.0, -1.0}) {
      glm::dvec3 e(0.0);
      e[axis] = side;
      if (n == e) return 2 * axis + (side < 0.0 ? 1 : 0);
    }
  return -1;
}

TEST(Aov, BoxFacesGiveExactAlbedoNormalDepthAndPosition) {
  const Box box;
  const shader::FrameParams p = box.Frame(48);
  std::unique_ptr<FrameRenderer> frame = BeginCpuFrame(box.cpu, p);
  frame->AddSamples(0, 1, {}, {});
  const AovSums aovs = frame->RenderAovs({16});
  ASSERT_EQ(aovs.samples, 16u);
  EXPECT_EQ(aovs.nonFinite, 0u);
  int exact = 0, background = 0, straddling = 0;
  for (size_t i = 0; i < aovs.pixels.size(); ++i) {
    const AovPixelSums& a = aovs.pixels[i];
    const glm::dvec3 normal = a.normal / 16.0, albedo = a.albedo / 16.0;
    if (a.hits == 0) {
      ++background;
      EXPECT_EQ(normal, glm::dvec3(0.0)) << i;
      EXPECT_EQ(a.depth, 0.0);
      // The background's radiance clamped to [0, 1].
      EXPECT_EQ(albedo, glm::dvec3(0.25, 0.5, 1.0)) << i;
      continue;
    }
    const int face = a.hits == 16 ? ExactFace(normal) : -1;
    if (face < 0) {
      ++straddling;
      EXPECT_LT(glm::length(normal), 1.0 + 1e-6) << i;
      continue;
    }
    ++exact;
    // Seen from outside: the outward normal of a face turned to the camera.
    EXPECT_GT(glm::dot(normal, glm::dvec3(kEye)), 0.0) << i;
    EXPECT_EQ(albedo, glm::dvec3(box.scene.materials[face].baseColor)) << i;
    const glm::dvec3 position = a.position / double(a.hits);
    EXPECT_NEAR(position[face / 2], face % 2 ? -1.0 : 1.0, 1e-6) << i;
    EXPECT_NEAR(a.depth / a.hits, glm::distance(position, glm::dvec3(kEye)), 2e-3) << i;
    EXPECT_GT(a.boxTests, 0.0);
  }
  std::printf("box 48²: %d pixels on one face, %d straddling, %d background\n", exact, straddling, background);
  EXPECT_GT(exact, 48 * 48 / 3);
  EXPECT_GT(background, 48 * 48 / 4);
  EXPECT_LT(straddling, 48 * 5);
}

TEST(Aov, MirrorShowsWhatItReflects) {
  // A smooth white metal +Z face: the AOVs walk on to what it reflects, the background
  // (the box is convex), so the albedo is the clamped background times the mirror's
  // reflectance and the normal is 0; depth and position stay those of the mirror.
  Material mirror{};
  mirror.baseColor = glm::vec3(1.0f);
  mirror.metallic = 1.0f;
  mirror.roughness = 0.0f;
  mirror.specularColor = glm::vec3(1.0f);
  mirror.specular = 1.0f;
  mirror.ior = 1.5f;
  const Box box(&mirror);
  const shader::FrameParams p = box.Frame(32);
  const AovSums aovs = BeginCpuFrame(box.cpu, p)->RenderAovs({4});
  int onMirror = 0;
  for (const AovPixelSums& a : aovs.pixels) {
    if (a.hits != 4) continue;
    const glm::dvec3 position = a.position / 4.0;
    if (std::abs(position.z - 1.0) > 1e-6 || std::abs(position.x) > 0.99 || std::abs(position.y) > 0.99) continue;
    ++onMirror;
    EXPECT_EQ(a.normal, glm::dvec3(0.0));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.albedo[c] / 4.0, std::min(1.0, double(kBackground[c])), 1e-5);
  }
  EXPECT_GT(onMirror, 32 * 32 / 10);
}

class AovGpu : public test::ValidatedGpuTest {};

TEST_F(AovGpu, MatchesTheCpu) {
  const Box box;
  const shader::FrameParams p = box.Frame(40);
  const AovSums cpu = BeginCpuFrame(box.cpu, p)->RenderAovs({8, true});
  vk::GpuRenderer renderer(test::Gpu(), box.gpu);
  const std::unique_ptr<FrameRenderer> frame = renderer.BeginFrame(p);
  const AovSums gpu = frame->RenderAovs({8, true});
  ASSERT_EQ(gpu.pixels.size(), cpu.pixels.size());
  ASSERT_EQ(gpu.samples, 8u);
  // Without ids no pixel's triangle is found, and every sum is the same.
  const AovSums withoutIds = frame->RenderAovs({8, false});
  int heatDiffers = 0, centresHit = 0;
  for (size_t i = 0; i < cpu.pixels.size(); ++i) {
    const AovPixelSums &c = cpu.pixels[i], &g = gpu.pixels[i], &n = withoutIds.pixels[i];
    ASSERT_EQ(c.hits, g.hits) << i;  // the same camera rays find the same surfaces
    ASSERT_EQ(c.triangle, g.triangle) << i;
    centresHit += g.triangle != shader::kInvalidIndex;
    ASSERT_EQ(n.triangle, shader::kInvalidIndex) << i;
    ASSERT_EQ(std::tie(n.albedo, n.normal, n.position, n.depth, n.boxTests, n.hits),
              std::tie(g.albedo, g.normal, g.position, g.depth, g.boxTests, g.hits))
        << i;
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(c.albedo[k], g.albedo[k], 1e-5) << i;
      EXPECT_NEAR(c.normal[k], g.normal[k], 1e-5) << i;
      EXPECT_NEAR(c.position[k], g.position[k], 1e-4) << i;
    }
    EXPECT_NEAR(c.depth, g.depth, 1e-4 * std::max(1.0, c.depth)) << i;
    // Both walks test boxes for every ray; they are different walks.
    EXPECT_GE(g.boxTests, 8.0) << i;
    heatDiffers += c.boxTests != g.boxTests;
  }
  EXPECT_GT(centresHit, 40 * 40 / 2);
  std::printf("box 40²: heat maps differ in %d pixels (different walks)\n", heatDiffers);
}

TEST(Aov, SppLayerFollowsTheNoise) {
  // Adaptive sampling gives more samples where a uniform render of another seed is
  // noisier: the spp AOV of the noisiest quarter of pixels exceeds the quietest quarter's.
  const Scene scene = LoadGltf(test::SourcePath("scenes/cornell.gltf"));
  const RenderScene rs = PrepareRenderScene(scene);
  shader::FrameParams p = MakeFrameParams(rs, scene.cameras[0], 24, 24);
  p.maxDepth = 32;
  p.rrDepth = 3;
  p.seed = 1;
  std::unique_ptr<FrameRenderer> uniform = BeginCpuFrame(rs, p);
  uniform->AddSamples(0, 64, {}, {});
  const FrameSums reference = uniform->Sums();
  p.seed = 2;
  std::unique_ptr<FrameRenderer> adaptive = BeginCpuFrame(rs, p);
  RenderBudget budget;
  budget.spp = 256;
  budget.adaptive = true;
  budget.adaptiveThreshold = 4e-3;
  const RenderedFrame r = test::RenderUnderBudget(*adaptive, budget);
  const std::vector<AovLayer> layers = ResolveAovs({Aov::kSpp}, {}, r.sums, ResolveFilm(r.sums), {});
  const float* spp = layers.at(0).values.data();
  std::vector<std::pair<double, float>> byNoise;
  for (size_t i = 0; i < reference.pixels.size(); ++i) {
    EXPECT_EQ(spp[i], float(r.sums.pixels[i].samples));
    byNoise.push_back({PixelRelativeError(reference.pixels[i]), spp[i]});
  }
  std::sort(byNoise.begin(), byNoise.end());
  const size_t q = byNoise.size() / 4;
  double quiet = 0.0, noisy = 0.0;
  for (size_t k = 0; k < q; ++k) {
    quiet += byNoise[k].second / q;
    noisy += byNoise[byNoise.size() - 1 - k].second / q;
  }
  std::printf("spp AOV: quietest quarter %.1f spp, noisiest quarter %.1f spp\n", quiet, noisy);
  EXPECT_GT(noisy, 1.3 * quiet);
}

TEST(Aov, IdsBeyondFloat32sIntegersAreRefused) {
  AovSums sums;
  sums.samples = 1;
  sums.pixels.resize(1);
  Image image(1, 1);
  const int64_t largest = int64_t(1) << 24;
  const std::vector<AovLayer> fine = ResolveAovs({Aov::kInstanceId}, sums, {}, image, [&](uint32_t) {
    return std::array<int64_t, 3>{0, 0, largest};
  });
  EXPECT_EQ(fine.at(0).values, std::vector<float>{float(largest)});
  // Ids 0 … 2^24 are exact; one more node, material or instance is refused, before a render.
  const uint64_t most = uint64_t(largest) + 1;
  EXPECT_NO_THROW(CheckIdsAreExact({most, most, most}, "big.glb"));
  const std::pair<IdCounts, const char*> beyond[] = {{{most + 1, 1, 1}, "16777218 nodes"},
                                                     {{1, most + 1, 1}, "16777218 materials"},
                                                     {{1, 1, most + 1}, "16777218 mesh instances"}};
  for (const auto& [counts, what] : beyond) {
    try {
      CheckIdsAreExact(counts, "big.glb");
      ADD_FAILURE() << what << " were accepted";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), std::string("big.glb: the id AOVs cannot label ") + what +
                                           ": ids beyond 2^24 are not exact in float32");
    }
  }
}

// The channel names of an EXR file.
std::vector<std::string> ExrChannels(const std::string& path) {
  EXRVersion version;
  EXPECT_EQ(ParseEXRVersionFromFile(&version, path.c_str()), TINYEXR_SUCCESS);
  EXRHeader header;
  InitEXRHeader(&header);
  const char* err = nullptr;
  EXPECT_EQ(ParseEXRHeaderFromFile(&header, &version, path.c_str(), &err), TINYEXR_SUCCESS);
  if (err) FreeEXRErrorMessage(err);
  std::vector<std::string> names;
  for (int c = 0; c < header.num_channels; ++c) names.push_back(header.channels[c].name);
  FreeEXRHeader(&header);
  return names;
}

TEST(AovCli, ExrHoldsNamedLayers) {
  const std::string dir = test::FreshTempDirectory("aov_exr");
  const test::ProcessResult r =
      test::RunVkpt({"--scene", test::SourcePath("scenes/cornell.gltf"), "--backend", "cpu", "--width", "16",
                     "--height", "16", "--spp", "4", "--aov", "all", "--out", dir + "/c.exr"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(test::DirectoryListing(dir), (std::vector<std::string>{"c.exr", "c.ids.json"}));
  const std::vector<std::string> expected = {
      "B",          "G",          "R",         "albedo.B",       "albedo.G",
      "albedo.R",   "depth.Z",    "heatmap.Y", "instance_id.ID", "material_id.ID",
      "normal.X",   "normal.Y",   "normal.Z",  "object_id.ID",   "position.X",
      "position.Y", "position.Z", "spp.Y",     "variance.B",     "variance.G",
      "variance.R"};
  EXPECT_EQ(ExrChannels(dir + "/c.exr"), expected);
  // The layers' values: every pixel of the Cornell box took 4 samples.
  float* rgba = nullptr;
  int w = 0, h = 0;
  const char* err = nullptr;
  ASSERT_EQ(LoadEXRWithLayer(&rgba, &w, &h, (dir + "/c.exr").c_str(), "spp", &err), TINYEXR_SUCCESS);
  ASSERT_EQ(w * h, 256);
  for (int i = 0; i < w * h; ++i) EXPECT_EQ(rgba[4 * i], 4.0f) << i;
  std::free(rgba);
}

TEST(AovCli, PngAndPfmFilesBesideTheImage) {
  const std::string dir = test::FreshTempDirectory("aov_png");
  for (const char* ext : {"png", "pfm"}) {
    const test::ProcessResult r =
        test::RunVkpt({"--scene", test::SourcePath("scenes/cornell.gltf"), "--width", "16", "--height", "16", "--spp",
                       "2", "--aov", "normal,spp,albedo", "--out", dir + "/c." + ext});
    ASSERT_EQ(r.exitCode, 0) << r.err;
  }
  EXPECT_EQ(test::DirectoryListing(dir),
            (std::vector<std::string>{"c.albedo.pfm", "c.albedo.png", "c.normal.pfm", "c.normal.png", "c.pfm", "c.png",
                                      "c.spp.pfm", "c.spp.png"}));
  const Image spp = ReadPfm(dir + "/c.spp.pfm");
  for (const glm::vec3& v : spp.pixels) EXPECT_EQ(v, glm::vec3(2.0f));
}

TEST(AovCli, UnknownNamesAndCompareAreUsageErrors) {
  const std::string scene = test::SourcePath("scenes/cornell.gltf");
  const std::string out = test::TempPath("aov_usage.png");  // never written: both are refused
  test::ProcessResult r = test::RunVkpt({"--scene", scene, "--aov", "albedo,glow", "--out", out});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("unknown AOV \"glow\""), std::string::npos) << r.err;
  r = test::RunVkpt({"--scene", scene, "--aov", "depth", "--compare", "--out", out});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("no --aov"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace vkpt::internal

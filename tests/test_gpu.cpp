// The Vulkan backend on lavapipe (or any device), with the validation layer on: every
// test ends by asserting that the layer reported nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <span>

#include "cpu/path_tracer.h"
#include "cpu/traversal.h"
#include "gltf/gltf_loader.h"
#include "gpu_test.h"
#include "image/image_compare.h"
#include "image/image_load.h"
#include "kPathTraceMutantNoLightCosine.h"
#include "kPathTraceMutantRouletteWithoutDivision.h"
#include "kSharedMathSpirv.h"
#include "kTraceLoopBudgetSpirv.h"
#include "render/light_table.h"
#include "render/render_scene.h"
#include "shared/estimator.h"
#include "shared/intersect.h"
#include "shared/rng.h"
#include "shared/sampling.h"
#include "test_util.h"
#include "vk/buffer.h"
#include "vk/compute_pipeline.h"
#include "vk/vk_renderer.h"

namespace vkpt::shader {
struct MathOut {
  uvec4 hash;
  vec4 rand;
  vec4 dir;
  vec4 misc;
  vec4 sobol;
};
}  // namespace vkpt::shader
#include "shaders/shared_math_body.glsl"

namespace vkpt::internal {
namespace {

using shader::FrameParams;
using test::Gpu;

class GpuTest : public test::ValidatedGpuTest {};

FrameParams Params(const RenderScene& rs, const Scene& scene, uint32_t w, uint32_t h, uint32_t spp, uint32_t seed,
                   uint32_t maxDepth = 32, uint32_t rrDepth = 3) {
  FrameParams p = MakeFrameParams(rs, scene.cameras.empty() ? DefaultCamera(scene.bounds) : scene.cameras[0], w, h);
  p.seed = seed;
  p.sampleCount = spp;
  p.maxDepth = maxDepth;
  p.rrDepth = rrDepth;
  if (rs.lights.empty()) p.background = glm::vec3(1.0f);
  return p;
}

TEST_F(GpuTest, SharedMathMatchesCpu) {
  const uint32_t n = 65536;
  vk::Buffer out(Gpu(), n * sizeof(shader::MathOut),
                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                 VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, "math out");
  vk::Buffer host(Gpu(), out.Size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                  VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, "math readback");
  vk::ComputePipeline pipe(Gpu(), kSharedMathSpirv, sizeof(kSharedMathSpirv),
                           {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, out.Handle()}}, "shared math");
  Gpu().Submit([&](VkCommandBuffer cb) {
    pipe.Dispatch(cb, n / 64, 1, 1);
    vk::CopyToHost(cb, {{&out, &host}});
  });
  const auto* gpu = static_cast<const shader::MathOut*>(host.Mapped());
  uint32_t hashDiff = 0, randDiff = 0, dirDiff = 0, miscDiff = 0;
  float maxDir = 0.0f, maxMisc = 0.0f;
  for (uint32_t i = 0; i < n; ++i) {
    shader::MathOut c = shader::Evaluate(i);
    hashDiff += c.hash != gpu[i].hash;
    randDiff += std::memcmp(&c.rand, &gpu[i].rand, sizeof c.rand) != 0;
    randDiff += std::memcmp(&c.sobol, &gpu[i].sobol, sizeof c.sobol) != 0;
    float d = glm::length(glm::vec3(c.dir) - glm::vec3(gpu[i].dir)) + std::abs(c.dir.w - gpu[i].dir.w);
    maxDir = std::max(maxDir, d);
    dirDiff += d > 1e-5f;
    glm::vec4 m = glm::abs(c.misc - gpu[i].misc);
    float md = std::max(std::max(m.x, m.y), std::max(m.z, m.w));
    maxMisc = std::max(maxMisc, md);
    miscDiff += md > 1e-5f;
  }
  std::printf(
      "%u inputs: hash mismatches %u, random-float and Sobol mismatches %u (bitwise); direction max error %.2e "
      "(%u > 1e-5); barycentric/box/triangle max error %.2e (%u > 1e-5)\n",
      n, hashDiff, randDiff, maxDir, dirDiff, maxMisc, miscDiff);
  EXPECT_EQ(hashDiff, 0u);
  EXPECT_EQ(randDiff, 0u);
  EXPECT_EQ(dirDiff, 0u);
  EXPECT_EQ(miscDiff, 0u);
}

// GPU closest hits vs the CPU: every ray must hit the same triangle at the same t,
// except on a true tie (equal t, another triangle). The CPU side is brute force for
// small scenes and the CPU's ordered traversal (itself checked against brute force in
// test_bvh) for the 100k-triangle model, where brute force would take minutes.
// Rays from around the scene's bounds: half aimed at random triangles, half in random
// directions, some parallel to the x = const planes.
std::vector<shader::RayQuery> RandomRays(const RenderScene& rs, uint32_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Bounds3f b{rs.nodes[0].lo, rs.nodes[0].hi};
  glm::vec3 ext = b.Diagonal();
  std::vector<shader::RayQuery> rays;
  for (uint32_t i = 0; i < count; ++i) {
    glm::vec3 o = b.lo - 0.25f * ext + 1.5f * ext * glm::vec3(u(rng), u(rng), u(rng));
    glm::vec3 d;
    if (i % 2) {
      const shader::Triangle& t =
          rs.triangles[std::min<size_t>(size_t(u(rng) * rs.triangles.size()), rs.triangles.size() - 1)];
      d = t.v0 + u(rng) * 0.5f * t.e1 + u(rng) * 0.5f * t.e2 - o;
    } else {
      d = glm::vec3(u(rng), u(rng), u(rng)) * 2.0f - 1.0f;
    }
    if (i % 17 == 0) d.x = 0.0f;
    if (glm::length(d) == 0.0f) d = glm::vec3(0, 0, 1);
    rays.push_back({o, shader::kInfinity, glm::normalize(d), 0});
  }
  return rays;
}

// `maxTexelsPerBuffer` > 0 caps the triangles' texel buffers, splitting them in two.
void CompareTraversal(const RenderScene& rs, uint32_t count, uint32_t seed, bool bruteForce,
                      uint32_t maxTexelsPerBuffer = 0) {
  std::vector<shader::RayQuery> rays = RandomRays(rs, count, seed);
  test::GpuRendererWith gpu(rs, {.maxTexelsPerBuffer = maxTexelsPerBuffer});
  std::vector<shader::HitRecord> hits = gpu.Trace(rays);
  uint32_t mismatches = 0, ties = 0, hitCount = 0;
  for (uint32_t i = 0; i < count; ++i) {
    const shader::RayQuery& r = rays[i];
    float refT = -1.0f;
    uint32_t refTri = shader::kInvalidIndex;
    if (bruteForce) {
      float tMax = r.tMax;
      for (uint32_t k = 0; k < rs.triangles.size(); ++k) {
        const shader::Triangle& t = rs.triangles[k];
        glm::vec3 h = shader::IntersectTriangle(t.v0, t.e1, t.e2, r.origin, r.dir, tMax);
        if (h.x >= 0.0f) refT = tMax = h.x, refTri = k;
      }
    } else {
      Hit h = IntersectClosest(rs, r.origin, r.dir, r.tMax);
      refT = h.t;
      refTri = h.triangle;
    }
    if (refT >= 0.0f) ++hitCount;
    if (hits[i].t != refT) {
      if (++mismatches <= 5)
        ADD_FAILURE() << "ray " << i << ": GPU t=" << hits[i].t << " tri " << hits[i].triangle << ", CPU t=" << refT
                      << " tri " << refTri;
    } else if (hits[i].triangle != refTri) {
      ++ties;
    }
  }
  std::printf("%u rays vs CPU %s: %u hits, %u ties, %u mismatches\n", count, bruteForce ? "brute force" : "traversal",
              hitCount, ties, mismatches);
  EXPECT_EQ(mismatches, 0u);
  EXPECT_GT(hitCount, count / 4);
}

TEST_F(GpuTest, TraversalMatchesCpuOnCornell) {
  Scene s = LoadGltf(test::SourcePath("scenes/cornell.gltf"));
  CompareTraversal(PrepareRenderScene(s), 65536, 1, true);
}

TEST_F(GpuTest, TraversalMatchesCpuOnRandomSoup) {
  Material m{};
  Scene s = test::MakeScene(test::RandomSoup(2000, 5), {m});
  CompareTraversal(PrepareRenderScene(s), 65536, 2, true);
}

// The triangles in two texel buffers, as on a device whose maxTexelBufferElements one
// buffer of them passes: 777 in the first, 1223 in the second.
TEST_F(GpuTest, TraversalMatchesCpuWithTrianglesInTwoBuffers) {
  Material m{};
  Scene s = test::MakeScene(test::RandomSoup(2000, 5), {m});
  CompareTraversal(PrepareRenderScene(s), 65536, 2, true, 777 * shader::kTexelsPerTriangle + 2);
}

TEST_F(GpuTest, TraversalMatchesCpuWithSpatialSplits) {
  Material m{};
  BvhBuildOptions o;
  o.splits = SplitMode::kSpatial;
  RenderScene rs = PrepareRenderScene(test::MakeScene(test::RandomSoup(2000, 8), {m}), o);
  ASSERT_GT(rs.triangles.size() + rs.degenerateTriangles, 2000u) << "the test needs duplicated triangles";
  CompareTraversal(rs, 65536, 6, true);
}

TEST_F(GpuTest, TraversalMatchesCpuOnLargeCorpusModel) {
  VKPT_REQUIRE_SHARED_DATA();
  Scene s = LoadGltf(test::CorpusPath("valid/2CylinderEngine/glTF-Binary/2CylinderEngine.glb"));
  ASSERT_GE(s.triangles.size(), 100000u);
  RenderScene rs = PrepareRenderScene(s);
  CompareTraversal(rs, 65536, 3, false);
  CompareTraversal(rs, 1024, 4, true);
}

// lavapipe ends a shader after 65535 loop passes per SIMD group; pathtrace.comp flags
// samples near that limit from the passes the traversal counts. The count must be exact:
// a probe loop sized from it must end right at the limit, and one pass longer must be
// cut (see tests/shaders/trace_loop_budget.comp).
TEST_F(GpuTest, TraversalCountsLoopPassesExactly) {
  // The loop limit is lavapipe's, and the suite pins lavapipe (tests/CMakeLists.txt).
  ASSERT_NE(Gpu().DeviceName().find("llvmpipe"), std::string::npos) << Gpu().DeviceName();
  Scene cornell = LoadGltf(std::string(VKPT_SOURCE_DIR) + "/scenes/cornell.gltf");
  std::vector<RenderScene> scenes;
  scenes.push_back(PrepareRenderScene(cornell));
  scenes.push_back(PrepareRenderScene(test::MakeScene(test::RandomSoup(3000, 11), {Material{}})));
  for (const RenderScene& rs : scenes) {
    test::GpuRendererWith gpu(rs, {.traceSpirv = kTraceLoopBudgetSpirv});
    std::vector<shader::RayQuery> rays = RandomRays(rs, 4096, 5);
    for (uint32_t beyond : {0u, 1u}) {
      for (shader::RayQuery& r : rays) r.pad0 = beyond;
      std::vector<shader::HitRecord> out = gpu.Trace(rays);
      uint32_t wrong = 0, minCounted = ~0u, maxCounted = 0;
      for (const shader::HitRecord& h : out) {
        uint32_t passes = glm::floatBitsToUint(h.t), probe = glm::floatBitsToUint(h.b1);
        uint32_t counted = glm::floatBitsToUint(h.b2);
        minCounted = std::min(minCounted, counted);
        maxCounted = std::max(maxCounted, counted);
        if (passes != probe - beyond && ++wrong <= 3)
          ADD_FAILURE() << "probe of " << probe << " passes ran " << passes << " after " << counted << " counted";
      }
      std::printf("%zu triangles, probe %s the limit: traversal counted %u..%u passes per SIMD group, %u wrong\n",
                  rs.triangles.size(), beyond ? "one past" : "ending at", minCounted, maxCounted, wrong);
      EXPECT_EQ(wrong, 0u);
      EXPECT_GT(minCounted, 6u) << "the traversal loops must have been counted";
    }
  }
}

// Same seed, same estimator code: the images agree pixel for pixel up to float rounding;
// a few pixels may differ where a rounding difference flips a branch.
TEST_F(GpuTest, LockstepCornellMatchesCpu) {
  Scene s = LoadGltf(test::SourcePath("scenes/cornell.gltf"));
  RenderScene rs = PrepareRenderScene(s);
  // 100 rows: 13 rows of tiles, the last one partial, dealt out with stride 8.
  FrameParams p = Params(rs, s, 128, 100, 4, 1);
  Image cpu = RenderCpu(rs, p).image;
  vk::GpuRenderer gpu(Gpu(), rs);
  RenderResult g = gpu.Render(p);
  EXPECT_EQ(g.nonFinite, 0u);
  ImageComparison c = CompareImages(cpu, g.image);
  std::printf("%s\n", c.Summary().c_str());
  EXPECT_LE(c.differingFraction, 0.01) << "at most 1 % of pixel channels beyond 1e-3 relative";
  EXPECT_EQ(c.nanA + c.nanB + c.infA + c.infB, 0u);
  EXPECT_TRUE(c.lockstepAgree);
}

// The glass slab of test_transmission.cpp on the GPU: refraction at ior 1.5, the η² of
// entering and leaving, Beer–Lambert inside — in lockstep with the CPU, and at the
// analytic value tint² e^{−2σ} in most pixels.
TEST_F(GpuTest, GlassSlabMatchesCpuAndBeerLambert) {
  const glm::vec3 tint(1.0f, 0.9f, 0.7f), sigma(0.1f, 0.5f, 1.5f), background(2.0f, 1.0f, 0.5f);
  Scene s = test::GlassSlabScene(test::ClearGlass(tint, sigma, 1.5f));
  RenderScene rs = PrepareRenderScene(s);
  FrameParams p = Params(rs, s, 48, 48, 4, 5, 8, 8);
  p.background = background;
  vk::GpuRenderer gpu(Gpu(), rs);
  RenderResult g = gpu.Render(p);
  const glm::vec3 through = background * tint * tint * glm::exp(-2.0f * sigma);
  const int near = test::PixelsNear(g.image, through, 1e-4f);
  ImageComparison c = CompareImages(RenderCpu(rs, p).image, g.image);
  std::printf("GPU glass slab: %d of %zu pixels within 1e-4 of tint^2 e^(-2 sigma) (>= 90 %%); vs CPU: %s\n", near,
              g.image.pixels.size(), c.Summary().c_str());
  EXPECT_EQ(g.nonFinite, 0u);
  EXPECT_GE(near, 0.9 * double(g.image.pixels.size()));
  EXPECT_TRUE(c.lockstepAgree);
}

// test_vertex_colors.cpp's quad on the GPU: COLOR_0 read from its texel buffer and
// interpolated, within each pixel's exact bound and in lockstep with the CPU.
TEST_F(GpuTest, VertexColorsMultiplyTheBaseColor) {
  const glm::vec3 base(0.8f, 0.6f, 1.0f);
  Scene s = test::VertexColorQuadScene(base);
  RenderScene rs = PrepareRenderScene(s);
  FrameParams p = Params(rs, s, 64, 64, 4, 3, 4, 4);
  p.background = glm::vec3(2.0f, 1.0f, 0.5f);
  vk::GpuRenderer gpu(Gpu(), rs);
  RenderResult g = gpu.Render(p);
  const int off = test::PixelsOffVertexColorQuad(g.image, p, base);
  ImageComparison c = CompareImages(RenderCpu(rs, p).image, g.image);
  std::printf(
      "GPU vertex-coloured quad: %d of %zu pixels outside their footprint's colour range (must be 0); vs CPU: %s\n",
      off, g.image.pixels.size(), c.Summary().c_str());
  EXPECT_EQ(off, 0);
  EXPECT_TRUE(c.lockstepAgree);
}

// An unlit quad with a NEAREST texture of 4 × 4 texels, 16 × 16 pixels each: every pixel
// is its texel decoded, bit for bit, on the GPU as on the CPU.
TEST_F(GpuTest, TexturedQuadShowsItsTexels) {
  Scene s = test::TexturedQuadScene();
  RenderScene rs = PrepareRenderScene(s);
  FrameParams p = Params(rs, s, 64, 64, 2, 3, 4, 4);
  p.background = glm::vec3(0.0f);
  vk::GpuRenderer gpu(Gpu(), rs);
  const int gpuOff = test::PixelsOffTexturedQuad(gpu.Render(p).image);
  const int cpuOff = test::PixelsOffTexturedQuad(RenderCpu(rs, p).image);
  // The store (5 texels) in two texel buffers of at most 2, as on a device whose
  // maxTexelBufferElements it passes: texels from the 9th word on come from the second.
  test::GpuRendererWith split(rs, {.maxTexelsPerBuffer = 2});
  const int splitOff = test::PixelsOffTexturedQuad(split.Render(p).image);
  std::printf(
      "textured quad: %d (GPU), %d (GPU, two texel buffers) and %d (CPU) of 4096 pixels differ from their texel\n",
      gpuOff, splitOff, cpuOff);
  EXPECT_EQ(gpuOff, 0);
  EXPECT_EQ(splitOff, 0);
  EXPECT_EQ(cpuOff, 0);
}

// The triangles and texture coordinates split over two texel buffers each, after the
// first triangle, the third, and half of them: the image is the one-buffer image, bit for
// bit, for the Cornell box, a textured square built in code and a textured corpus model.
void ExpectArraysInTwoBuffersRenderTheSameImage(vk::Context& gpu, const Scene& s, const std::string& path) {
  RenderScene rs = PrepareRenderScene(s);
  FrameParams p = Params(rs, s, 48, 40, 8, 3);
  const Image one = vk::GpuRenderer(gpu, rs).Render(p).image;
  int identical = 0, splits = 0;
  for (uint32_t split : {1u, 3u, uint32_t(rs.triangles.size()) / 2}) {
    if (split >= rs.triangles.size()) continue;  // the two-triangle square: after the first only
    ++splits;
    const Image two =
        test::GpuRendererWith(rs, {.maxTexelsPerBuffer = split * shader::kTexelsPerTriangle}).Render(p).image;
    const bool same = two.pixels == one.pixels && two.variance == one.variance;
    EXPECT_TRUE(same) << path << ": " << split << " triangles in the first buffer";
    identical += same;
  }
  std::printf(
      "%s (%zu triangles, %zu with texture coordinates), arrays in two texel buffers: %d of %d splits "
      "render the same bytes\n",
      path.c_str(), rs.triangles.size(), rs.uvs.size(), identical, splits);
}

TEST_F(GpuTest, ArraysInTwoBuffersRenderTheSameImage) {
  VKPT_SKIP_UNDER_ADDRESS_SANITIZER("a bit-identity of the buffer split, 13 s (its textured twin skips too)");
  const std::string cornell = test::SourcePath("scenes/cornell.gltf");
  ExpectArraysInTwoBuffersRenderTheSameImage(Gpu(), LoadGltf(cornell), cornell);
  ExpectArraysInTwoBuffersRenderTheSameImage(Gpu(), test::TexturedQuadScene(), "the textured square");
}

TEST_F(GpuTest, ArraysInTwoBuffersRenderTheSameImageTextured) {
#if defined(VKPT_ADDRESS_SANITIZER)
  GTEST_SKIP() << "14 s under AddressSanitizer; the untextured test's square is textured, the plain build runs it";
#endif
  VKPT_REQUIRE_SHARED_DATA();
  const std::string path = test::CorpusPath("valid/BoxTextured/glTF/BoxTextured.gltf");
  ExpectArraysInTwoBuffersRenderTheSameImage(Gpu(), LoadGltf(path), path);
}

// Path regeneration (pathtrace.comp) adds each invocation's samples in sample order, as
// separate dispatches would: the image must not depend on how samples are grouped.
TEST_F(GpuTest, ImageDoesNotDependOnSamplesPerInvocation) {
#if defined(VKPT_ADDRESS_SANITIZER)
  GTEST_SKIP() << "13 s under AddressSanitizer for the shader's dispatch shape; the plain build runs it";
#endif
  Scene s = LoadGltf(test::SourcePath("scenes/cornell.gltf"));
  RenderScene rs = PrepareRenderScene(s);
  FrameParams p = Params(rs, s, 40, 24, 13, 3);
  vk::GpuRenderer gpu(Gpu(), rs);
  std::vector<RenderResult> results;
  for (uint32_t run : {1u, 4u, 13u, 0u}) {
    vk::GpuRenderOptions o;
    o.samplesPerInvocation = run;
    o.batch = run ? 0 : 5;  // adaptive: one measuring dispatch, then batches of 5
    results.push_back(gpu.Render(p, o));
    const RenderResult& r = results.back();
    EXPECT_EQ(r.cutShort, 0u);
    EXPECT_EQ(r.nonFinite, 0u);
    if (run) {
      EXPECT_EQ(r.samplesPerInvocation, run);
    }
  }
  EXPECT_GT(results.back().samplesPerInvocation, 1u) << "the adaptive run length must group samples on Cornell";
  for (size_t i = 1; i < results.size(); ++i) {
    EXPECT_EQ(results[i].rays, results[0].rays);
    EXPECT_TRUE(results[i].image.pixels == results[0].image.pixels) << "run " << i;
    EXPECT_TRUE(results[i].image.variance == results[0].image.variance) << "run " << i;
  }
}

// A run of samples too long for lavapipe's loop limit must be reported as cut short,
// never returned as a silently darker image.
TEST_F(GpuTest, RunPastTheLoopLimitIsReported) {
  // The loop limit is lavapipe's, and the suite pins lavapipe (tests/CMakeLists.txt).
  ASSERT_NE(Gpu().DeviceName().find("llvmpipe"), std::string::npos) << Gpu().DeviceName();
  Scene s = LoadGltf(test::SourcePath("scenes/cornell.gltf"));
  RenderScene rs = PrepareRenderScene(s);
  FrameParams p = Params(rs, s, 8, 8, 2000, 1);
  vk::GpuRenderer gpu(Gpu(), rs);
  vk::GpuRenderOptions o;
  o.samplesPerInvocation = p.sampleCount;
  RenderResult r = gpu.Render(p, o);
  std::printf("2000 samples per invocation: %llu of %u samples flagged as cut short\n", (unsigned long long)r.cutShort,
              64 * p.sampleCount);
  EXPECT_GT(r.cutShort, 0u);
}

// Independent seeds: region means must agree within their standard errors. The same
// test must reject deliberately wrong shaders (proof that it has teeth).
ImageComparison IndependentComparison(std::span<const uint32_t> spirv, const char* name) {
  Scene s = LoadGltf(test::SourcePath("scenes/cornell.gltf"));
  RenderScene rs = PrepareRenderScene(s);
  Image cpu = RenderCpu(rs, Params(rs, s, 64, 64, 64, 1)).image;
  test::GpuRendererWith gpu(rs, {.pathTraceSpirv = spirv});
  Image g = gpu.Render(Params(rs, s, 64, 64, 64, 2)).image;
  ImageComparison c = CompareImages(cpu, g);
  std::printf("[%s]\n%s\n", name, c.Summary().c_str());
  return c;
}

TEST_F(GpuTest, IndependentCornellAgreesStatistically) {
  EXPECT_TRUE(IndependentComparison({}, "pathtrace.comp").statisticallyAgree);
}

TEST_F(GpuTest, MutantWithoutLightCosineIsCaught) {
  VKPT_SKIP_UNDER_ADDRESS_SANITIZER("a mutant's rejection, 6 s");
  EXPECT_FALSE(IndependentComparison(kPathTraceMutantNoLightCosine, "mutant: no cos at the light").statisticallyAgree);
}

TEST_F(GpuTest, MutantRouletteWithoutDivisionIsCaught) {
  VKPT_SKIP_UNDER_ADDRESS_SANITIZER("a mutant's rejection, 6 s");
  EXPECT_FALSE(IndependentComparison(kPathTraceMutantRouletteWithoutDivision, "mutant: roulette without 1/P")
                   .statisticallyAgree);
}

test::ZTest GpuFurnace(std::span<const uint32_t> spirv, glm::dvec3* expected) {
  Scene s = LoadGltf(test::SourcePath("scenes/furnace.gltf"));
  RenderScene rs = PrepareRenderScene(s);
  test::GpuRendererWith gpu(rs, {.pathTraceSpirv = spirv});
  RenderResult r = gpu.Render(Params(rs, s, 32, 32, 128, 9, 200, 3));
  EXPECT_EQ(r.nonFinite, 0u);
  *expected = test::FurnaceExpected(s, 200);
  return test::MeanAndError(r.image, *expected);
}

TEST_F(GpuTest, FurnaceMatchesClosedForm) {
  glm::dvec3 expected;
  test::ZTest t = GpuFurnace({}, &expected);
  EXPECT_TRUE(test::Agrees(t, expected, 1e-3, "GPU furnace"));
}

TEST_F(GpuTest, FurnaceCatchesBothMutants) {
  VKPT_SKIP_UNDER_ADDRESS_SANITIZER("two mutants' rejection, 13 s");
  glm::dvec3 expected;
  test::ZTest a = GpuFurnace(kPathTraceMutantNoLightCosine, &expected);
  EXPECT_FALSE(test::Agrees(a, expected, 1e-3, "GPU furnace, mutant no light cosine (must fail)"));
  test::ZTest b = GpuFurnace(kPathTraceMutantRouletteWithoutDivision, &expected);
  EXPECT_FALSE(test::Agrees(b, expected, 1e-3, "GPU furnace, mutant roulette without 1/P (must fail)"));
}

class GpuCorpus : public GpuTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(GpuCorpus, RendersOnTheGpu) {
#if defined(VKPT_ADDRESS_SANITIZER)
  GTEST_SKIP() << "25 models, 110 s under AddressSanitizer; CorpusValid loads each under it, other GPU tests upload";
#endif
  VKPT_REQUIRE_SHARED_DATA();
  Scene s = LoadGltf(test::CorpusPath("valid/" + GetParam()));
  RenderScene rs = PrepareRenderScene(s);
  FrameParams p = Params(rs, s, 24, 24, 2, 1);
  vk::GpuRenderer gpu(Gpu(), rs);
  RenderResult r = gpu.Render(p);
  EXPECT_EQ(r.nonFinite, 0u);
  EXPECT_EQ(r.cutShort, 0u);
  // Lockstep with the CPU reference on the same seed.
  ImageComparison c = CompareImages(RenderCpu(rs, p).image, r.image);
  std::printf("%s: %.3f %% of channels beyond 1e-3 relative, max rel error %.2e\n", GetParam().c_str(),
              100.0 * c.differingFraction, c.maxRelError);
  EXPECT_TRUE(c.lockstepAgree) << c.Summary();
}

std::vector<std::string> ValidModels() {
  std::vector<std::string> out;
  std::filesystem::path root = test::CorpusPath("valid");
  if (test::SharedDataDir().empty()) return {};  // TraversalMatchesCpuOnLargeCorpusModel skips
  if (!std::filesystem::exists(root)) return {"(corpus missing: " + root.string() + ")"};
  for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
    std::string ext = e.path().extension().string();
    if (ext == ".gltf" || ext == ".glb") out.push_back(std::filesystem::relative(e.path(), root).string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(GpuCorpus);
INSTANTIATE_TEST_SUITE_P(Valid, GpuCorpus, ::testing::ValuesIn(ValidModels()), [](const auto& info) {
  std::string n = info.param;
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
});

// ---------------------------------------------------------------------------------------
// The glTF PBR models of gltf-pbr/ in the test data (its MANIFEST.md), read in place: each loads
// (with its textures, where it has any), lists what vkpt does not render yet, and
// renders on both backends, lockstep with the CPU on the same seed and statistically with
// an independent one, without a validation message.

struct PbrModel {
  std::string file;                     // under `collection`
  bool textured;                        // MANIFEST.md lists images for it
  std::string collection = "gltf-pbr";  // a folder of the external test data
  double lockstepFraction = 0.01;       // the share of channels that may differ in lockstep
  SceneChoice pose = {};                // an animation and time to pose it at
};

void PrintTo(const PbrModel& m, std::ostream* os) { *os << m.file; }

std::string PbrPath(const std::string& relative) { return test::SharedData("gltf-pbr/" + relative); }

// Object splits only: the BVH is not under test here, and the automatic choice, which
// builds spatial splits too, takes 5.5 s instead of 1.2 on the 1 M-triangle sphere grid.
RenderScene PreparePbr(const Scene& s) {
  BvhBuildOptions o;
  o.splits = SplitMode::kObject;
  return PrepareRenderScene(s, o);
}

// The CPU (seed 1) against the GPU with the same seed (lockstep: at most
// `lockstepFraction` of the channels beyond 1e-3) and with seed 2 (region z-tests,
// Šidák-corrected).
void ExpectBackendsAgree(const RenderScene& rs, FrameParams p, const std::string& what,
                         double lockstepFraction = 0.01) {
  RenderResult cpu = RenderCpu(rs, p);
  vk::GpuRenderer gpu(Gpu(), rs);
  RenderResult same = gpu.Render(p);
  p.seed = 2;
  RenderResult independent = gpu.Render(p);
  for (const RenderResult* r : {&cpu, &same, &independent}) {
    EXPECT_EQ(r->nonFinite, 0u) << what;
    EXPECT_EQ(r->cutShort, 0u) << what;
  }
  CompareOptions lockstepOptions;
  lockstepOptions.maxDifferingFraction = lockstepFraction;
  ImageComparison lockstep = CompareImages(cpu.image, same.image, lockstepOptions);
  ImageComparison stats = CompareImages(cpu.image, independent.image);
  std::printf("%s, same seed: %.3f %% of channels beyond 1e-3 relative (limit %.0f %%), max rel error %.2e\n",
              what.c_str(), 100.0 * lockstep.differingFraction, 100.0 * lockstep.options.maxDifferingFraction,
              lockstep.maxRelError);
  std::printf(
      "%s, independent seeds: worst |z| %.2f, smallest p %.3g vs Sidak threshold %.3g (%d tests), "
      "%d significant regions beyond the %.0f %% margin\n",
      what.c_str(), stats.worstZ, stats.worstP, stats.alphaPerTest, stats.tests, stats.significantRegions,
      100.0 * stats.options.margin);
  EXPECT_TRUE(lockstep.lockstepAgree) << what << "\n" << lockstep.Summary();
  EXPECT_TRUE(stats.statisticallyAgree) << what << "\n" << stats.Summary();
}

class GpuPbrCorpus : public GpuTest, public ::testing::WithParamInterface<PbrModel> {};

TEST_P(GpuPbrCorpus, LoadsAndRendersAlikeOnBothBackends) {
#if defined(VKPT_ADDRESS_SANITIZER)
  GTEST_SKIP() << "22 models, 109 s under AddressSanitizer; their loading and upload run under it in other tests";
#endif
  VKPT_REQUIRE_SHARED_DATA();
  const std::string path = test::SharedData(GetParam().collection + "/" + GetParam().file);
  ASSERT_TRUE(std::filesystem::exists(path)) << path << " is missing";
  Scene s = LoadGltf(path, {}, GetParam().pose);
  std::string ignored;
  for (const std::string& f : s.ignoredFeatures) ignored += (ignored.empty() ? "" : "; ") + f;
  std::printf("%s: %zu triangles, %zu materials, %zu lights; ignored: %s\n", GetParam().file.c_str(),
              s.triangles.size(), s.materials.size(), s.lights.size(), ignored.empty() ? "nothing" : ignored.c_str());
  EXPECT_EQ(!s.textures.empty(), GetParam().textured) << ignored;
  RenderScene rs = PreparePbr(s);
  ExpectBackendsAgree(rs, Params(rs, s, 32, 32, 16, 1, 8), GetParam().file, GetParam().lockstepFraction);
}

INSTANTIATE_TEST_SUITE_P(
    GltfPbr, GpuPbrCorpus,
    ::testing::Values(
        PbrModel{"SpecularTest/glTF-Binary/SpecularTest.glb", true},
        PbrModel{"TransmissionTest/glTF-Binary/TransmissionTest.glb", true},
        PbrModel{"TransmissionRoughnessTest/glTF-Binary/TransmissionRoughnessTest.glb", true},
        PbrModel{"LightsPunctualLamp/glTF/LightsPunctualLamp.gltf", true},
        PbrModel{"EmissiveStrengthTest/glTF-Binary/EmissiveStrengthTest.glb", true},
        PbrModel{"MultiUVTest/glTF-Binary/MultiUVTest.glb", true},
        PbrModel{"TextureTransformTest/glTF/TextureTransformTest.gltf", true},
        PbrModel{"TextureLinearInterpolationTest/glTF-Binary/TextureLinearInterpolationTest.glb", true},
        PbrModel{"NormalTangentMirrorTest/glTF-Binary/NormalTangentMirrorTest.glb", true},
        PbrModel{"AlphaBlendModeTest/glTF-Binary/AlphaBlendModeTest.glb", true},
        PbrModel{"ClearCoatTest/glTF-Binary/ClearCoatTest.glb", true, "gltf-ext"},
        PbrModel{"ClearcoatWicker/glTF-Binary/ClearcoatWicker.glb", true, "gltf-ext"},
        // Its normal map, repeated 30 times, parts the backends' paths in 1.2 %
        // of the channels, with or without the sheen (1.27 % without).
        PbrModel{"SheenCloth/glTF/SheenCloth.gltf", true, "gltf-ext", 0.02},
        PbrModel{"IridescenceSuzanne/glTF-Binary/IridescenceSuzanne.glb", true, "gltf-ext"},
        PbrModel{"AnisotropyStrengthTest/glTF-Binary/AnisotropyStrengthTest.glb", true, "gltf-ext"},
        PbrModel{"DispersionTest/glTF-Binary/DispersionTest.glb", true, "gltf-ext"},
        PbrModel{"AttenuationTest/glTF-Binary/AttenuationTest.glb", true, "gltf-ext"},
        PbrModel{"GlassVaseFlowers/glTF-Binary/GlassVaseFlowers.glb", true, "gltf-ext"},
        // Its normal map parts the paths in 0.94 % of the channels.
        PbrModel{"IridescenceAbalone/glTF/IridescenceAbalone.gltf", true, "gltf-ext", 0.02},
        // Draco-compressed geometry.
        PbrModel{"Duck/glTF-Draco/Duck.gltf", true, "gltf-ext"},
        // Skinned, posed by an animation.
        PbrModel{"Fox/glTF-Binary/Fox.glb", true, "gltf-ext", 0.01, {.animation = "Run", .time = 0.4}},
        PbrModel{
            "RiggedSimple/glTF-Binary/RiggedSimple.glb", false, "gltf-ext", 0.01, {.animation = "0", .time = 1.0}}),
    [](const auto& info) {
      std::string n = info.param.file.substr(0, info.param.file.find('/'));
      return n;
    });

// A renderer of a new upload of the scene on the same device compiles nothing: its
// kernels come from the device's PipelineCache (a frame sequence depends on it), and its
// image is the first's, bit for bit. A change of what the kernel is specialized for (a
// clear coat in the scene) compiles one pipeline more: the cache tells kernels apart.
TEST_F(GpuTest, SecondRendererReusesTheCompiledPipeline) {
  Scene s = LoadGltf(test::SourcePath("scenes/cornell.gltf"));
  const RenderScene first = PrepareRenderScene(s);
  const FrameParams params = Params(first, s, 24, 24, 4, 7, 8);
  const Image a = vk::GpuRenderer(Gpu(), first).Render(params).image;
  const size_t compiled = Gpu().Pipelines().Compiled();
  const RenderScene second = PrepareRenderScene(s);
  const Image b = vk::GpuRenderer(Gpu(), second).Render(params).image;
  EXPECT_EQ(Gpu().Pipelines().Compiled(), compiled);
  EXPECT_EQ(a.pixels, b.pixels);
  s.materials[0].clearcoat = 1.0f;
  const RenderScene coated = PrepareRenderScene(s);
  vk::GpuRenderer(Gpu(), coated).Render(params);
  EXPECT_EQ(Gpu().Pipelines().Compiled(), compiled + 1);
}

// The generated hall of 2,000 emissive triangles, with point and spot lights hung among
// them, lit through the light tree: its descent and the emitters' tree pmfs in lockstep
// on both backends, and in statistics with other seeds.
TEST_F(GpuTest, LightTreeAgreesOnBothBackends) {
  Scene s = LoadGltf(test::SourcePath("scenes/many_lights.gltf"));
  for (int i = 0; i < 16; ++i) {
    PunctualLight l;
    l.type = i % 2 ? PunctualLight::Type::kSpot : PunctualLight::Type::kPoint;
    l.position = glm::vec3(2.5f * i + 1.0f, 3.0f + 0.1f * i, 3.0f + (i % 5) * 3.0f);
    l.direction = glm::normalize(glm::vec3(0.3f * (i % 3) - 0.3f, -1.0f, 0.2f));
    l.intensity = glm::vec3(1.0f + i, 2.0f, 3.0f);
    l.cosOuter = 0.6f;
    l.cosInner = 0.9f;
    s.lights.push_back(l);
  }
  RenderScene rs = PrepareRenderScene(s);
  ChooseLightSampler(rs, LightSampler::kTree);
  ASSERT_EQ(rs.treeLights, 2016u);
  ExpectBackendsAgree(rs, Params(rs, s, 48, 48, 16, 1, 8), "many_lights hall through the light tree");
}

// The Cornell box with a clear coat on every material (rough on the walls, smooth on the
// boxes, half on the light, which dims its emission): the coat lobe, its sampling and the
// dimmed emission in lockstep on both backends, and in statistics with other seeds.
TEST_F(GpuTest, ClearcoatedCornellAgreesOnBothBackends) {
  Scene s = LoadGltf(test::SourcePath("scenes/cornell.gltf"));
  for (size_t m = 0; m < s.materials.size(); ++m) {
    s.materials[m].clearcoat = m % 2 ? 1.0f : 0.5f;
    s.materials[m].clearcoatRoughness = m % 3 ? 0.4f : 0.05f;
  }
  RenderScene rs = PrepareRenderScene(s);
  ExpectBackendsAgree(rs, Params(rs, s, 48, 48, 16, 1, 8), "clear-coated Cornell box");
}

// The Cornell box with a sheen on every material (colours and roughnesses varied), every
// one passing part of its diffuse base through, tinted, a clear coat on every other one
// and a thin film on the rest (thicknesses varied), anisotropic on two of three (without
// tangents: each frame's own x axis): the sheen lobe, its table and sampler, the
// diffusely transmitted lobe, light sampled through walls and escaping the box, the
// film's Fresnel, the anisotropic lobe, and the layering, in lockstep on both backends and
// in statistics with other seeds.
TEST_F(GpuTest, LayeredMaterialsCornellAgreesOnBothBackends) {
  Scene s = LoadGltf(test::SourcePath("scenes/cornell.gltf"));
  for (size_t m = 0; m < s.materials.size(); ++m) {
    s.materials[m].sheenColor = m % 2 ? glm::vec3(1.0f, 0.8f, 0.6f) : glm::vec3(0.5f);
    s.materials[m].sheenRoughness = m % 3 ? 0.3f : 0.8f;
    s.materials[m].diffuseTransmission = m % 2 ? 0.5f : 0.9f;
    s.materials[m].diffuseTransmissionColor = glm::vec3(1.0f, 0.8f, 0.6f);
    s.materials[m].clearcoat = m % 2 ? 0.0f : 1.0f;
    s.materials[m].clearcoatRoughness = 0.2f;
    s.materials[m].iridescence = m % 2 ? 1.0f : 0.0f;
    s.materials[m].iridescenceThicknessMax = m % 3 ? 300.0f : 700.0f;
    s.materials[m].roughness = 0.4f;
    s.materials[m].anisotropyStrength = m % 3 ? 0.8f : 0.0f;
    s.materials[m].anisotropyRotation = 0.5f * float(m);
  }
  RenderScene rs = PrepareRenderScene(s);
  ExpectBackendsAgree(rs, Params(rs, s, 48, 48, 16, 1, 8), "layered Cornell box");
}

// A generated map (test::RleHdr: a row of suns at the top, runs and ramps elsewhere), read
// as --env FILE reads it and turned 30°, lighting a Lambert square that fills the frame:
// the environment's importance sampling on both backends, without the test data.
TEST_F(GpuTest, GeneratedEnvironmentMapAgreesOnBothBackends) {
  const test::TempFolder dir("gpu-env");
  std::ofstream(dir / "map.hdr", std::ios::binary) << test::RleHdr(64, 32);
  std::vector<std::string> warnings;
  const Image image = ReadEnvironmentImage(
      dir / "map.hdr", [](uint64_t, const std::string&) {}, &warnings);
  const Scene s = test::VertexColorQuadScene(glm::vec3(0.8f));
  RenderScene rs = PrepareRenderScene(s);
  rs.environment = BuildEnvironmentMap(image.width, image.height, image.pixels);
  AddEnvironmentLight(rs, 1.0f);
  FrameParams p = Params(rs, s, 32, 32, 16, 1, 8);
  SetEnvironmentParams(p, rs.environment, 30.0f, 1.0f);
  EXPECT_EQ(test::PixelsNear(RenderCpu(rs, p).image, glm::vec3(0.0f), 0.0f), 0)
      << "black pixels: the map lights nothing";
  ExpectBackendsAgree(rs, p, "a Lambert square under a generated map");
}

// The metal/roughness sphere grid (1.04 M triangles, one BVH for all three renders) under
// the white background and under each of the two environment maps (as --env FILE).
TEST_F(GpuTest, PbrSpheresUnderBackgroundAndBothEnvironmentsAgree) {
#if defined(VKPT_ADDRESS_SANITIZER)
  GTEST_SKIP() << "1 M triangles, 26 s under AddressSanitizer; the plain build runs it";
#endif
  VKPT_REQUIRE_SHARED_DATA();
  const std::string path = PbrPath("MetalRoughSpheresNoTextures/glTF-Binary/MetalRoughSpheresNoTextures.glb");
  ASSERT_TRUE(std::filesystem::exists(path)) << path << " is missing";
  Scene s = LoadGltf(path);
  std::printf("MetalRoughSpheresNoTextures: %zu triangles, %zu materials, %zu ignored features\n", s.triangles.size(),
              s.materials.size(), s.ignoredFeatures.size());
  EXPECT_TRUE(s.ignoredFeatures.empty()) << s.ignoredFeatures[0];
  const RenderScene base = PreparePbr(s);
  ExpectBackendsAgree(base, Params(base, s, 32, 32, 16, 1, 8), "MetalRoughSpheresNoTextures, white background");
  for (const char* map : {"venice_sunset_1k.hdr", "potsdamer_platz_1k.hdr"}) {
    std::vector<std::string> warnings;
    Image image = ReadEnvironmentImage(
        PbrPath(std::string("environments/") + map), [](uint64_t, const std::string&) {}, &warnings);
    RenderScene rs = base;
    rs.environment = BuildEnvironmentMap(image.width, image.height, image.pixels);
    AddEnvironmentLight(rs, 1.0f);
    FrameParams p = Params(rs, s, 32, 32, 16, 1, 8);
    SetEnvironmentParams(p, rs.environment, 0.0f, 1.0f);
    ExpectBackendsAgree(rs, p, std::string("MetalRoughSpheresNoTextures under ") + map);
  }
}

}  // namespace
}  // namespace vkpt::internal

namespace vkpt::internal {
namespace {

// The validation layer's reports are counted (vk::ValidationCounter): without that, every
// ValidatedGpuTest, and the viewer's window tests, would pass blind.
TEST(VulkanValidation, AnInvalidCallIsCounted) {
  vk::ContextOptions o;
  o.validation = true;
  vk::Context ctx(o);
  const uint32_t before = ctx.ValidationMessages();
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = 0;  // VUID-VkBufferCreateInfo-size-00912: it must be greater than 0
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  vkCreateBuffer(ctx.Device(), &info, nullptr, &buffer);
  if (buffer != VK_NULL_HANDLE) vkDestroyBuffer(ctx.Device(), buffer, nullptr);
  EXPECT_GT(ctx.ValidationMessages(), before);
}

}  // namespace
}  // namespace vkpt::internal

// Texture level of detail must not bias the converged image: on normal-mapped, textured
// models lit by a white background, the default --texture-lod cones converges to the
// image of --texture-lod none (level 0 everywhere), judged by region z-tests (8 × 8
// regions, Šidák-corrected, 1 % margin) at 1,024 spp on both backends, and a mutant that
// filters every texture by its cone at every vertex (normal maps and roughness too, at the
// camera's hit too: vkpt before path.h's TextureCones) must fail the same test.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "cpu/path_tracer.h"
#include "gltf/gltf_loader.h"
#include "gpu_test.h"
#include "image/image_compare.h"
#include "path_variants.h"
#include "render/render_scene.h"
#include "test_util.h"
#include "vk/vk_renderer.h"

namespace vkpt::internal {
namespace {

struct LodModel {
  const char* path;  // under the external test data
  const char* name;
};
const LodModel kModels[] = {
    {"gltf-corpus/valid/DamagedHelmet/glTF-Binary/DamagedHelmet.glb", "DamagedHelmet"},
    {"gltf-pbr/NormalTangentMirrorTest/glTF-Binary/NormalTangentMirrorTest.glb", "NormalTangentMirrorTest"},
};

constexpr uint32_t kSize = 48, kSpp = 1024;

// kSize² pixels of the default camera (glTF's, else the one framing the scene), `spp`
// samples from seed `seed`, paths of up to 8 bounces, under a white background.
shader::FrameParams Frame(const RenderScene& rs, const Scene& s, uint32_t spp, uint32_t seed, bool cones) {
  shader::FrameParams p = MakeFrameParams(rs, s.cameras.empty() ? DefaultCamera(s.bounds) : s.cameras[0], kSize, kSize);
  p.seed = seed;
  p.sampleCount = spp;
  p.maxDepth = 8;
  p.background = glm::vec3(1.0f);
  p.textureLod = cones ? 1u : 0u;
  return p;
}

CompareOptions Tiles() {
  CompareOptions o;
  o.regionSize = 8;
  return o;
}

// `cones` (seed 1) against `none` (seed 2, --texture-lod none): whether they agree.
bool Agree(const char* what, const Image& cones, const Image& none) {
  const ImageComparison c = CompareImages(cones, none, Tiles());
  std::printf("%s: relMSE %.5f, worst |z| %.2f (p %.3g vs Sidak %.3g over %d tests), %d of %d regions beyond %.0f %%\n",
              what, RelativeMse(cones, none), c.worstZ, c.worstP, c.alphaPerTest, c.tests, c.significantRegions,
              c.regions, 100.0 * c.options.margin);
  return c.statisticallyAgree;
}

class TextureLod : public test::ValidatedGpuTest {};

TEST_F(TextureLod, ConesConvergeToLevelZeroOnBothBackends) {
#if defined(VKPT_ADDRESS_SANITIZER)
  GTEST_SKIP() << "a convergence statistic, 31 s under AddressSanitizer; the plain build runs it";
#endif
  VKPT_REQUIRE_SHARED_DATA();
  for (const LodModel& m : kModels) {
    const std::string path = test::SharedData(m.path);
    ASSERT_TRUE(std::filesystem::exists(path)) << path;
    Scene s = LoadGltf(path);
    RenderScene rs = PrepareRenderScene(s);
    const shader::FrameParams cones = Frame(rs, s, kSpp / test::kSampleDivisor, 1, true);
    const shader::FrameParams none = Frame(rs, s, kSpp / test::kSampleDivisor, 2, false);
    vk::GpuRenderer gpu(test::Gpu(), rs);
    const std::string name = m.name;
    EXPECT_TRUE(Agree((name + ", CPU").c_str(), RenderCpu(rs, cones).image, RenderCpu(rs, none).image));
    EXPECT_TRUE(Agree((name + ", GPU").c_str(), gpu.Render(cones).image, gpu.Render(none).image));
  }
}

TEST_F(TextureLod, MutantFilteringEverythingIsCaught) {
#if defined(VKPT_ADDRESS_SANITIZER)
  GTEST_SKIP() << "the convergence test's mutant, 15 s under AddressSanitizer; the plain build runs it";
#endif
  VKPT_REQUIRE_PATH_VARIANTS();
  VKPT_REQUIRE_SHARED_DATA();
  int caught = 0;
  for (const LodModel& m : kModels) {
    Scene s = LoadGltf(test::SharedData(m.path));
    RenderScene rs = PrepareRenderScene(s);
    const shader::FrameParams cones = Frame(rs, s, kSpp, 1, true), none = Frame(rs, s, kSpp, 2, false);
    caught += !Agree((std::string(m.name) + ", mutant: every texture filtered everywhere").c_str(),
                     test::RenderMutantTexturesFilteredEverywhere(rs, cones).image, RenderCpu(rs, none).image);
  }
  EXPECT_EQ(caught, 2);
}

}  // namespace
}  // namespace vkpt::internal

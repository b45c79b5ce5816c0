// KHR_materials_transmission and KHR_materials_volume in whole renders: Beer–Lambert
// attenuation inside a volume, the η² factors of entering and leaving it, the tint of
// each crossing, and which side of a surface light sampling may look on. (The BSDF
// itself is tested in test_bsdf.cpp; the GPU twin of the slab test is in test_gpu.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "cpu/path_tracer.h"
#include "render/render_scene.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

shader::FrameParams SlabParams(const Scene& s, const RenderScene& rs, glm::vec3 background) {
  shader::FrameParams p = MakeFrameParams(rs, s.cameras[0], 48, 48);
  p.seed = 5;
  p.sampleCount = 4;
  p.maxDepth = 8;
  p.rrDepth = 8;
  p.background = background;
  return p;
}

// Through the slab: two crossings, each tinted by baseColor (radiance divided by ior² on
// entering, multiplied back on leaving), and 2 units of absorption: tint² e^{−2σ} in
// most pixels and in the image mean. Not in every pixel: the GGX lobe's long tail
// (Walter et al. 2007) bends a few samples by tenths of a radian even at the smallest
// roughness, lengthening their path. The tolerance tells apart an absorption 5 % off
// (checked: the test has teeth).
TEST(Transmission, GlassSlabAttenuatesByBeerLambert) {
  const glm::vec3 tint(1.0f, 0.9f, 0.7f), sigma(0.1f, 0.5f, 1.5f), background(2.0f, 1.0f, 0.5f);
  for (float ior : {1.0f, 1.5f}) {
    Scene s = test::GlassSlabScene(test::ClearGlass(tint, sigma, ior));
    RenderScene rs = PrepareRenderScene(s);
    RenderResult r = RenderCpu(rs, SlabParams(s, rs, background));
    const glm::vec3 through = background * tint * tint * glm::exp(-2.0f * sigma);
    const glm::vec3 wrong = background * tint * tint * glm::exp(-2.0f * 0.95f * sigma);
    const int pixels = int(r.image.pixels.size());
    const int near = test::PixelsNear(r.image, through, 1e-4f), nearWrong = test::PixelsNear(r.image, wrong, 1e-4f);
    glm::dvec3 mean(0.0);
    for (const glm::vec3& px : r.image.pixels) mean += glm::dvec3(px) / double(pixels);
    const glm::dvec3 meanRatio = mean / glm::dvec3(through);
    std::printf(
        "ior %.1f: %d of %d pixels (>= 90 %%) within 1e-4 of (%.5f %.5f %.5f), image mean / that "
        "(%.5f %.5f %.5f) (within 1e-3); %d pixels at an absorption 5 %% lower (must be 0)\n",
        ior, near, pixels, through.x, through.y, through.z, meanRatio.x, meanRatio.y, meanRatio.z, nearWrong);
    EXPECT_GE(near, pixels * 0.9) << "ior " << ior;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(meanRatio[c], 1.0, 1e-3) << "ior " << ior << ", channel " << c;
    EXPECT_EQ(nearWrong, 0) << "ior " << ior;
  }
}

// A white rough glass sphere (ior 1.5, no absorption) in a white furnace: every pixel
// is 1 when each crossing and reflection keeps its energy — the rough dielectric's
// compensation (shared/bsdf.h) — and paths run until roulette ends them (light trapped by
// total internal reflection needs hundreds of bounces). Single scattering alone gave
// 0.9755 at roughness 0.3 and 0.83 at 1.
TEST(Transmission, RoughGlassSphereInAWhiteFurnaceReturnsOne) {
  for (float roughness : {0.3f, 1.0f}) {
    Material glass = test::ClearGlass(glm::vec3(1.0f), glm::vec3(0.0f), 1.5f);
    glass.specular = 1.0f;
    glass.roughness = roughness;
    Scene s = test::SphereInFurnace(glass);
    RenderScene rs = PrepareRenderScene(s);
    RenderResult r = RenderCpu(rs, test::SphereFurnaceParams(rs, s, 11));
    EXPECT_EQ(r.nonFinite, 0u);
    const test::ZTest z = test::MeanAndError(r.image, glm::dvec3(1.0));
    std::printf("rough glass sphere furnace, roughness %.1f: mean %.4f +- %.4f (must be 1 within 1 %%)\n", roughness,
                z.mean.y, z.stderr_.y);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(z.mean[c], 1.0, 0.01) << "roughness " << roughness << ", channel " << c;
  }
}

}  // namespace
}  // namespace vkpt::internal

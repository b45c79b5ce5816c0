// vkpt::ProgressiveRender: steps of samples give Render's image bit for bit, on both
// backends; a render ends when its scene moves on; Render's budgets are refused; a
// cancelled step keeps what it took.
#include <memory>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "api_test_util.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal {
namespace {

// 24 × 16 pixels in chunks of 4, with an AOV and the filter, so that the result's every
// part is compared.
vkpt::RenderOptions Options(uint32_t spp) {
  vkpt::RenderOptions o = test::SmallRender(5);
  o.spp = spp;
  o.aovs = {"albedo", "depth"};
  o.denoise = true;
  return o;
}

void ExpectSame(const vkpt::RenderResult& a, const vkpt::RenderResult& b, const std::string& what) {
  EXPECT_EQ(a.image.data, b.image.data) << what;
  ASSERT_TRUE(a.raw && b.raw) << what;
  EXPECT_EQ(a.raw->data, b.raw->data) << what;
  ASSERT_EQ(a.aovs.size(), b.aovs.size()) << what;
  for (const auto& [name, aov] : a.aovs) EXPECT_EQ(aov.data, b.aovs.at(name).data) << what << " " << name;
  EXPECT_EQ(a.spp, b.spp) << what;
  EXPECT_EQ(a.samples, b.samples) << what;
  EXPECT_EQ(a.estimatedRelMse, b.estimatedRelMse) << what;
}

TEST(ApiProgressive, StepsGiveRendersImageBitForBit) {
  for (const vkpt::Backend backend : {vkpt::Backend::Cpu, vkpt::Backend::Vulkan}) {
    vkpt::Scene scene = test::Open(test::Cornell(), backend);
    const std::string on = scene.Device();
    const vkpt::RenderResult at6 = scene.Render({}, Options(6));
    const vkpt::RenderResult at16 = scene.Render({}, Options(16));
    vkpt::ProgressiveRender steps = scene.Begin({}, Options(16));
    EXPECT_EQ(steps.MaxSpp(), 16u);
    EXPECT_EQ(steps.Advance(), 1u);
    EXPECT_EQ(steps.Advance(5), 6u);  // across the first chunk's end
    const vkpt::RenderResult r6 = steps.Result();
    ExpectSame(r6, at6, on + " at 6 spp");
    EXPECT_EQ(r6.stoppedBy, "");
    EXPECT_EQ(steps.Advance(100), 16u);  // the bound
    EXPECT_EQ(steps.Advance(), 16u);
    const vkpt::RenderResult r16 = steps.Result();
    ExpectSame(r16, at16, on + " at 16 spp");
    EXPECT_EQ(r16.stoppedBy, "spp");
    EXPECT_NE(r6.image.data, r16.image.data);
    EXPECT_EQ(steps.Camera().index, 0u);
    EXPECT_EQ(steps.Camera().position, scene.Cameras()[0].position);
  }
}

TEST(ApiProgressive, WithoutASppBoundTakesUpTo65536) {
  vkpt::Scene scene = test::Open(test::Cornell(), vkpt::Backend::Cpu);
  vkpt::RenderOptions o = test::SmallRender();
  o.spp.reset();
  EXPECT_EQ(scene.Begin({}, o).MaxSpp(), 65536u);
}

TEST(ApiProgressive, EndsWhenItsSceneMovesOn) {
  auto scene = std::make_unique<vkpt::Scene>(test::Open(test::Cornell(), vkpt::Backend::Cpu));
  const auto expectEnded = [](vkpt::ProgressiveRender& r, const std::string& after) {
    try {
      r.Advance();
      ADD_FAILURE() << "still advancing after " << after;
    } catch (const vkpt::Error& e) {
      EXPECT_NE(std::string(e.what()).find("this progressive render has ended"), std::string::npos) << e.what();
    }
    EXPECT_THROW(r.Result(), vkpt::Error) << after;
    EXPECT_THROW(r.Spp(), vkpt::Error) << after;
  };
  vkpt::ProgressiveRender first = scene->Begin({}, test::SmallRender());
  first.Advance();
  vkpt::ProgressiveRender second = scene->Begin({}, test::SmallRender());
  expectEnded(first, "a second Begin");
  EXPECT_EQ(second.Advance(), 1u);
  scene->Render({}, test::SmallRender());
  expectEnded(second, "a Render");
  vkpt::ProgressiveRender third = scene->Begin({}, test::SmallRender());
  EXPECT_THROW(scene->Update({{"environment/intensity", 1.0}}), vkpt::SettingError);  // no map: nothing ends
  EXPECT_EQ(third.Advance(), 1u);
  scene->Update({{"materials/0/roughness", 0.5}});
  expectEnded(third, "an Update");
  vkpt::ProgressiveRender fourth = scene->Begin({}, test::SmallRender());
  vkpt::ProgressiveRender moved = std::move(fourth);
  EXPECT_EQ(moved.Advance(), 1u);
  scene.reset();
  expectEnded(moved, "the scene's end");
}

TEST(ApiProgressive, RefusesRendersBudgets) {
  vkpt::Scene scene = test::Open(test::Cornell(), vkpt::Backend::Cpu);
  for (const char* budget : {"seconds", "noiseTarget", "adaptive"}) {
    vkpt::RenderOptions o = test::SmallRender();
    if (budget == std::string("seconds")) o.seconds = 1.0;
    if (budget == std::string("noiseTarget")) o.noiseTarget = 0.01;
    if (budget == std::string("adaptive")) o.adaptive = true;
    try {
      scene.Begin({}, o);
      ADD_FAILURE() << budget << " accepted";
    } catch (const vkpt::SettingError& e) {
      EXPECT_NE(std::string(e.what()).find("seconds, noiseTarget and adaptive are Render's"), std::string::npos)
          << e.what();
    }
  }
  vkpt::RenderOptions bad = test::SmallRender();
  bad.maxDepth = 100000;
  EXPECT_THROW(scene.Begin({}, bad), vkpt::SettingError);  // the render's own checks
}

TEST(ApiProgressive, ACancelledStepKeepsItsSamplesAndTheNextGoesOn) {
  vkpt::Scene scene = test::Open(test::Cornell(), vkpt::Backend::Cpu);
  vkpt::RenderOptions o = test::SmallRender();
  o.spp = 64;
  bool stop = false;
  double lastProgress = 0.0;
  o.cancel = [&] { return stop; };
  o.progress = [&](double f) { lastProgress = f; };
  vkpt::ProgressiveRender r = scene.Begin({}, o);
  EXPECT_EQ(r.Advance(8), 8u);
  EXPECT_DOUBLE_EQ(lastProgress, 8.0 / 64.0);
  stop = true;
  EXPECT_EQ(r.Advance(8), 8u);  // asked between passes: nothing more taken
  EXPECT_EQ(r.Result().stoppedBy, "cancelled");
  stop = false;
  EXPECT_EQ(r.Advance(8), 16u);
  const vkpt::RenderResult result = r.Result();
  EXPECT_EQ(result.stoppedBy, "");
  EXPECT_EQ(result.spp, 16u);
}

}  // namespace
}  // namespace vkpt::internal

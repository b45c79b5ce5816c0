// The engine (engine/loaded_scene.h): one load renders any number of views and poses, each
// bit for bit what a fresh load of the same file renders, while the arrays are built once
// per pose and uploaded once per build.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "engine/loaded_scene.h"
#include "gltf_builder.h"
#include "session/local_passes.h"
#include "session/render_session.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

using namespace test;

FrameRequest View(double orbit, double time = 0.0) {
  FrameRequest r;
  r.camera.orbit = orbit;
  r.picture.width = 24;
  r.picture.height = 16;
  r.picture.maxDepth = 32;
  r.picture.rrDepth = 3;
  r.picture.textureLod = true;
  r.picture.time = time;
  return r;
}

Image RenderOn(LoadedScene& scene, const FrameRequest& request) {
  const PreparedFrame frame = scene.Prepare(request);
  const std::unique_ptr<FrameRenderer> renderer = scene.BeginFrame(frame.params, 0);
  LocalPasses source(*renderer, 4);
  SessionSettings settings;
  settings.budget.spp = 4;
  settings.budget.chunkSpp = 4;
  return RenderSession(source, settings).image;
}

bool SameBits(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)) == 0;
}

SceneSettings Settings(const std::string& path, Backend backend) {
  SceneSettings s;
  s.path = path;
  s.backend = backend;
  s.validation = backend == Backend::Vulkan;
  return s;
}

// Views of one load, in an order that goes back to the first: each equals a fresh load's.
void ExpectViewsEqualFreshLoads(const SceneSettings& settings, const std::vector<FrameRequest>& views,
                                uint32_t builds) {
  LoadedScene once(settings, {});
  std::vector<Image> images;
  for (const FrameRequest& view : views) images.push_back(RenderOn(once, view));
  EXPECT_EQ(once.Counts().builds, builds);
  EXPECT_EQ(once.Counts().uploads, settings.backend == Backend::Vulkan ? builds : 0u);
  for (size_t i = 0; i < views.size(); ++i) {
    LoadedScene fresh(settings, {});
    EXPECT_TRUE(SameBits(images[i], RenderOn(fresh, views[i]))) << "view " << i;
    if (fresh.Device()) {
      EXPECT_EQ(fresh.Device()->ValidationMessages(), 0u);
    }
  }
  EXPECT_FALSE(SameBits(images[0], images[1]));  // the views differ
  if (once.Device()) {
    EXPECT_EQ(once.Device()->ValidationMessages(), 0u);
  }
}

TEST(Engine, ViewsOfOneLoadEqualFreshLoads) {
  ExpectViewsEqualFreshLoads(Settings(SourcePath("scenes/cornell.gltf"), Backend::Cpu),
                             {View(0.0), View(40.0), View(0.0)}, 1);
}

TEST(Engine, VulkanViewsShareOneUpload) {
  ExpectViewsEqualFreshLoads(Settings(SourcePath("scenes/cornell.gltf"), Backend::Vulkan), {View(0.0), View(40.0)}, 1);
}

// An animated scene is posed and built again when the time changes, not when it stays.
TEST(Engine, PosesOfOneLoadEqualFreshLoads) {
  const TempFile model(SlidingTriangle());
  SceneSettings settings = Settings(model.path, Backend::Cpu);
  settings.choice.animation = "slide";
  std::vector<FrameRequest> poses = {View(0.0, 0.0), View(0.0, 0.5), View(20.0, 0.5), View(0.0, 0.0)};
  for (FrameRequest& pose : poses) {
    pose.camera.lookFrom = glm::vec3(0.5f, 0.5f, 3.0f);
    pose.camera.lookAt = glm::vec3(0.5f, 0.5f, 0.0f);
  }
  ExpectViewsEqualFreshLoads(settings, poses, 3);
}

}  // namespace
}  // namespace vkpt::internal

// The one validated Vulkan context every GPU test of the program shares, and the fixture
// that ends each GPU test by asserting the validation layer reported nothing.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>

#include "render/render_scene.h"
#include "vk/context.h"
#include "vk/vk_renderer.h"

namespace vkpt::internal::test {

// Created on first use (device creation costs ~100 ms), with the validation layer on.
vk::Context& Gpu();

// A GpuRenderer on Gpu() with some of its kernels or limits replaced (deliberately wrong
// kernels, probes, small texel buffers): vk::GpuRendererOverrides, through the renderer's
// protected constructor.
class GpuRendererWith : public vk::GpuRenderer {
 public:
  GpuRendererWith(const RenderScene& scene, const vk::GpuRendererOverrides& overrides)
      : GpuRenderer(Gpu(), scene, overrides) {}
};

class ValidatedGpuTest : public ::testing::Test {
 protected:
  void TearDown() override {
    EXPECT_EQ(Gpu().ValidationMessages(), before_) << "the Vulkan validation layer reported messages";
  }
  uint32_t before_ = Gpu().ValidationMessages();
};

}  // namespace vkpt::internal::test

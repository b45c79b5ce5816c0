// The Vulkan backend: the scene uploaded once as storage buffers, then pathtrace.comp
// dispatched in batches of samples per pixel, then the per-pixel sums read back.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "image/image.h"
#include "render/render_scene.h"
#include "vk/buffer.h"
#include "vk/context.h"

namespace vkpt::vk {

struct GpuRenderOptions {
  // Samples per pixel per submission; 0 picks about 2^20 paths per submission, short
  // enough that a desktop GPU's watchdog never fires.
  uint32_t batch = 0;
  std::function<void(double)> progress;  // finished fraction, after every batch
};

struct GpuRenderResult {
  Image image;  // mean and variance of the mean per pixel
  uint64_t rays = 0;
  uint64_t nonFinite = 0;
  double seconds = 0.0;  // dispatches and readback, not upload or pipeline creation
  uint32_t batches = 0;
};

class GpuRenderer {
 public:
  // Uploads the scene. `spirv` defaults to the embedded pathtrace.comp; tests pass
  // deliberately wrong variants.
  GpuRenderer(const Context& ctx, const RenderScene& scene, const uint32_t* spirv = nullptr, size_t spirvBytes = 0);
  GpuRenderResult Render(const shader::FrameParams& params, const GpuRenderOptions& options = {});

 private:
  const Context& ctx_;
  const uint32_t* spirv_;
  size_t spirvBytes_;
  Buffer triangles_, nodes_, materials_, emitters_;
};

}  // namespace vkpt::vk

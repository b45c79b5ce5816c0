// This process's renderer of a scene's frames: on the Vulkan device when there is one (the
// scene uploaded once, for every frame), else on the CPU; and the denoiser that goes with it.
#pragma once

#include <memory>

#include "render/film.h"
#include "render/render_scene.h"
#include "session/render_session.h"
#include "shared/layout.h"
#include "vk/context.h"
#include "vk/vk_renderer.h"

namespace vkpt::internal {

class RenderBackend {
 public:
  // `ctx` null: the CPU with `threads` threads (0: all cores). `rs` must outlive this.
  RenderBackend(const vk::Context* ctx, const RenderScene& rs, unsigned threads);

  // A frame of the scene (its kernels compiled on first use of the device). `batch`:
  // Vulkan samples per pixel per submission (0: automatic). It must not outlive this.
  std::unique_ptr<FrameRenderer> BeginFrame(const shader::FrameParams& params, uint32_t batch) const;
  Denoiser MakeDenoiser() const;
  // The scene's materials and light table changed in place (RestyleRenderScene), and its
  // triangles' light indices where `triangleLights`: the device's copies are uploaded
  // again; the CPU reads them as they are.
  void Restyle(bool triangleLights);
  const char* DenoiserName() const { return ctx_ ? "vulkan" : "cpu"; }

 private:
  const vk::Context* ctx_;
  const RenderScene& rs_;
  unsigned threads_;
  std::unique_ptr<vk::GpuRenderer> gpu_;  // the scene on the device
};

}  // namespace vkpt::internal

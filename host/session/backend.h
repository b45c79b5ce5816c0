// This process's renderer of a frame: on the Vulkan device when there is one (its scene
// uploaded, its pipeline compiled), else on the CPU; and the denoiser that goes with it.
#pragma once

#include <memory>

#include "render/film.h"
#include "render/render_scene.h"
#include "session/render_session.h"
#include "shared/layout.h"
#include "vk/context.h"
#include "vk/vk_renderer.h"

namespace vkpt {

class RenderBackend {
 public:
  // `ctx` null: the CPU with `threads` threads (0: all cores). `batch`: Vulkan samples
  // per pixel per submission (0: automatic). `rs` must outlive this.
  RenderBackend(const vk::Context* ctx, const RenderScene& rs, const shader::FrameParams& params, uint32_t batch,
                unsigned threads);

  FrameRenderer& Frame() { return *frame_; }
  Denoiser MakeDenoiser() const;
  const char* DenoiserName() const { return ctx_ ? "vulkan" : "cpu"; }
  double UploadSeconds() const { return uploadSeconds_; }  // the scene to the device, the pipeline compiled

 private:
  const vk::Context* ctx_;
  unsigned threads_;
  std::unique_ptr<vk::GpuRenderer> gpu_;  // keeps the device's scene alive with the frame
  std::unique_ptr<FrameRenderer> frame_;
  double uploadSeconds_ = 0.0;
};

}  // namespace vkpt

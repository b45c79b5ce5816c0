// What vkpt prints about a run: the load report (-v), the progress line on a terminal,
// the summary after a render, and the --compare verdict.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "app/options.h"
#include "session/render_session.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal {

// -v: what the scene holds, and the camera `cam` of the frame begun.
void PrintLoadReport(const vkpt::Scene& scene, const vkpt::CameraInfo& cam);

// "rendering: 42.0%" rewritten in place on a terminal (empty when stderr is not one), and
// its erasure when the render is over.
std::function<void(double)> ProgressLine();
void EndProgressLine();

// The summary after a render: samples and why they stopped, rates, the image's mean, the
// scene and its BVH, warnings; then the ranks, the AOVs and the denoised image, and the
// `files` written (--out first).
void PrintRenderReport(const vkpt::SceneStats& scene, const RenderedFrame& frame, const Options& o,
                       const std::vector<std::string>& files, const char* denoiser);

// --compare: the CPU reference (A) against the Vulkan render (B), with a heat map beside
// the output. Same seed, same estimator: the backends must agree pixel by pixel
// (lockstep) and in every region's mean (statistics); 4 if they do not, else 0.
int CompareBackends(const RenderedFrame& reference, const RenderedFrame& frame, const Options& o);

}  // namespace vkpt::internal

// A render in progress on the device (GpuRenderer::BeginFrame): the frame's buffers and
// path-tracing pipeline, kept from pass to pass so the sums persist in device memory
// exactly as within one pass; samples go in submissions of runs of samples per invocation.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "render/film.h"
#include "shared/layout.h"
#include "vk/buffer.h"
#include "vk/compute_pipeline.h"
#include "vk/context.h"
#include "vk/vk_renderer.h"

namespace vkpt::internal::vk {

// pathtrace.comp's per-render buffers: per pixel Σf and Σf² (two vec4), the counters
// (rays, non-finite samples, samples cut short, samples) and the adaptive sampling mask;
// the frame constants; the loop passes per sample of the last submission's worst SIMD
// group; host copies of the sums and counters.
struct FrameBuffers {
  Buffer accum, counters, active, params, loopStats, accumHost, countersHost;
};

FrameBuffers MakeFrameBuffers(const Context& ctx, uint64_t pixels);

// The frame constants' binding in every kernel of the frame: a storage buffer
// (pathtrace.comp says why).
BufferBinding FrameParamsBinding(const FrameBuffers& b);

// A kernel over the scene (scene_constants.glsl) with the given per-frame bindings.
using KernelFactory = std::function<std::unique_ptr<ComputePipeline>(const uint32_t* spirv, size_t spirvBytes,
                                                                     std::vector<BufferBinding> frameBindings,
                                                                     const char* name, uint32_t pushConstantBytes)>;

// Zeroes a frame's sums and counters on the device.
void ClearSums(const Context& ctx, const FrameBuffers& b);

// How a frame's dispatches have gone so far: the run of samples per invocation, and
// whether a dispatch has measured the scene's loop passes yet.
struct RunState {
  uint32_t run = 1;
  bool measured = false;
  uint32_t batches = 0;               // submissions
  uint32_t samplesPerInvocation = 0;  // the longest run used
};

// The frame on `pipeline` (pathtrace.comp over `b`); `kernels` makes the AOV kernel.
std::unique_ptr<FrameRenderer> MakeGpuFrame(const Context& ctx, FrameBuffers b,
                                            std::unique_ptr<ComputePipeline> pipeline, KernelFactory kernels,
                                            const shader::FrameParams& frame, const GpuRenderOptions& options);
// The dispatches so far of a frame MakeGpuFrame made.
const RunState& GpuFrameState(const FrameRenderer& frame);

}  // namespace vkpt::internal::vk

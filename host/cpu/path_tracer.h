// The CPU reference path tracer: the estimator every other backend is checked against.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>

#include "render/film.h"
#include "render/render_scene.h"

namespace vkpt::internal {

struct SampleStats {
  uint64_t rays = 0;       // closest-hit + shadow rays
  uint64_t nonFinite = 0;  // samples discarded because they were NaN/Inf (a bug if > 0)
};

// Radiance carried by sample `sampleIndex` of pixel (px, py) — one path. Uses the RNG
// streams (params.seed, pixel, sampleIndex, dimension) shared with the GPU.
glm::vec3 SampleRadiance(const RenderScene& scene, const shader::FrameParams& params, uint32_t px, uint32_t py,
                         uint32_t sampleIndex, SampleStats& stats);

// Whether the scene is simple — Lambertian materials, flat triangles without vertex
// colours, triangle lights only, no environment map (the Cornell box) — and SampleRadianceSimple, the same estimator
// compiled for such scenes alone (simple_path.cpp), renders it as SampleRadiance does.
bool IsSimpleScene(const RenderScene& scene, const shader::FrameParams& params);
glm::vec3 SampleRadianceSimple(const RenderScene& scene, const shader::FrameParams& params, uint32_t px, uint32_t py,
                               uint32_t sampleIndex, SampleStats& stats);

// Whether no material a triangle uses has a layered extension (clear coat, sheen, diffuse
// transmission, iridescence, anisotropy, dispersion) — and SampleRadianceCore, the same
// estimator compiled without them (core_path.cpp), renders such a scene as
// SampleRadiance does.
bool IsCoreScene(const RenderScene& scene);
glm::vec3 SampleRadianceCore(const RenderScene& scene, const shader::FrameParams& params, uint32_t px, uint32_t py,
                             uint32_t sampleIndex, SampleStats& stats);

struct CpuRenderOptions {
  unsigned threads = 0;  // 0: all hardware threads
  // Called from the calling thread about every 100 ms with the finished fraction.
  std::function<void(double)> progress;
};

// A render in progress on the CPU (params.sampleBegin and sampleCount are ignored: each
// pass names its samples). Each pixel's samples are summed in sample order, so the image
// is bit-identical for any thread count and any division into passes. `scene` must
// outlive it.
std::unique_ptr<FrameRenderer> BeginCpuFrame(const RenderScene& scene, const shader::FrameParams& params,
                                             unsigned threads = 0);

// Renders samples [params.sampleBegin, params.sampleBegin + params.sampleCount) of every
// pixel in one pass of a BeginCpuFrame render.
RenderResult RenderCpu(const RenderScene& scene, const shader::FrameParams& params,
                       const CpuRenderOptions& options = {});

}  // namespace vkpt::internal

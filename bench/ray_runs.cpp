#include "ray_runs.h"

#include <algorithm>
#include <cmath>

#include "cpu/traversal.h"
#include "shared/intersect.h"
#include "shared/rng.h"
#include "shared/sampling.h"
#include "util/parallel.h"

namespace vkpt::internal::bench {

RaySets MakeRays(const RenderScene& rs, const shader::FrameParams& p, unsigned threads) {
  RaySets r;
  r.camera.resize(size_t(p.width) * p.height);
  for (uint32_t y = 0; y < p.height; ++y)
    for (uint32_t x = 0; x < p.width; ++x) {
      shader::Ray ray = shader::GenerateCameraRay(p, x, y, 0.5f, 0.5f);
      r.camera[size_t(y) * p.width + x] = {ray.origin, shader::kInfinity, ray.dir, 0};
    }
  std::vector<Hit> hits(r.camera.size());
  ParallelFor(
      hits.size(), threads,
      [&](size_t i) { hits[i] = IntersectClosest(rs, r.camera[i].origin, r.camera[i].dir, r.camera[i].tMax); },
      kRayGrain);
  for (size_t i = 0; i < hits.size(); ++i) {
    if (hits[i].t < 0.0f) continue;
    const shader::Triangle& t = rs.triangles[hits[i].triangle];
    glm::vec3 ng = glm::normalize(glm::cross(t.e1, t.e2));
    if (glm::dot(ng, r.camera[i].dir) > 0.0f) ng = -ng;
    glm::vec3 p0 = t.v0 + hits[i].b1 * t.e1 + hits[i].b2 * t.e2;
    glm::vec4 u = shader::Random4(1u, uint32_t(i), 0u, 0u);
    glm::vec3 d = shader::FrameToWorld(shader::FrameFromNormal(ng), shader::SampleCosineHemisphere(u.x, u.y));
    r.diffuse.push_back({shader::OffsetRayOrigin(p0, ng), shader::kInfinity, d, 0});
  }
  return r;
}

TraceRun TraceCpu(const RenderScene& rs, const std::vector<shader::RayQuery>& rays, unsigned threads) {
  TraceRun run;
  run.t.resize(rays.size());
  auto t0 = Clock::now();
  ParallelFor(
      rays.size(), threads,
      [&](size_t i) { run.t[i] = IntersectClosest(rs, rays[i].origin, rays[i].dir, rays[i].tMax).t; }, kRayGrain);
  run.seconds = Seconds(t0);
  return run;
}

TraceRun TraceGpu(vk::GpuRenderer& gpu, const std::vector<shader::RayQuery>& rays) {
  TraceRun run;
  std::vector<shader::HitRecord> hits = gpu.Trace(rays, &run.seconds);
  run.t.reserve(hits.size());
  for (const shader::HitRecord& h : hits) run.t.push_back(h.t);
  return run;
}

uint64_t Mismatches(const TraceRun& a, const TraceRun& b) {
  uint64_t n = 0;
  for (size_t i = 0; i < a.t.size(); ++i) {
    bool ha = a.t[i] >= 0.0f, hb = b.t[i] >= 0.0f;
    if (ha != hb || (ha && std::abs(a.t[i] - b.t[i]) > 1e-4f * std::max(1.0f, a.t[i]))) ++n;
  }
  return n;
}

}  // namespace vkpt::internal::bench

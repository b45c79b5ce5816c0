// Path tracing with next-event estimation and Russian roulette (GAMES101 lecture 16,
// `shade(p, wo)`; Kajiya 1986): at every path vertex, direct light is estimated by
// sampling a point on an emissive triangle (area sampling, dω = cos θ' dA / r²) and the
// path continues along a cosine-weighted direction. Emission is added only where the
// camera ray hits an emitter directly; light reaching later vertices is counted by the
// light samples, so nothing is counted twice. Rays that escape collect the constant
// environment radiance (FrameParams::background). All surfaces are Lambertian, f = ρ/π.
#include "cpu/path_tracer.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include "cpu/traversal.h"
#include "shared/estimator.h"
#include "shared/intersect.h"
#include "shared/rng.h"
#include "shared/sampling.h"

namespace vkpt {

using namespace shader;

namespace {

glm::vec3 GeometricNormal(const Triangle& t) { return glm::normalize(glm::cross(t.e1, t.e2)); }

}  // namespace

glm::vec3 SampleRadiance(const RenderScene& scene, const FrameParams& params, uint32_t px, uint32_t py,
                         uint32_t sampleIndex, SampleStats& stats) {
  const uint32_t pixel = py * params.width + px;
  const auto rand = [&](uint32_t group) { return Random4(params.seed, pixel, sampleIndex, group); };

  vec4 uc = rand(kGroupCamera);
  Ray ray = GenerateCameraRay(params, px, py, uc.x, uc.y);
  vec3 radiance(0.0f);
  vec3 throughput(1.0f);

  for (uint32_t bounce = 0;; ++bounce) {
    ++stats.rays;
    Hit hit = IntersectClosest(scene.nodes, scene.triangles, ray.origin, ray.dir, kInfinity);
    if (!hit.Valid()) {
      // Escaped: light from the constant environment. It is never light-sampled, so
      // counting it here on every bounce counts it exactly once.
      radiance += throughput * params.background;
      break;
    }
    const Triangle& tri = scene.triangles[hit.triangle];
    const Material& mat = scene.materials[tri.material];
    const vec3 ng = GeometricNormal(tri);
    const bool frontFace = dot(ng, ray.dir) < 0.0f;
    if (bounce == 0 && (frontFace || (mat.flags & kMaterialDoubleSided)))
      radiance += throughput * mat.emission;
    // Paths have at most maxDepth bounces: the light sample at vertex k, and the ray
    // leaving it (which may escape to the environment), make k + 1.
    if (bounce >= params.maxDepth) break;

    // Surfaces reflect on both sides: shade with the normal facing the incoming ray.
    const vec3 n = frontFace ? ng : -ng;
    const vec3 p = tri.v0 + hit.b1 * tri.e1 + hit.b2 * tri.e2;
    const vec3 brdf = mat.baseColor * kInvPi;
    const vec3 origin = OffsetRayOrigin(p, n);

    vec4 ul = rand(LightGroup(bounce));
    if (!scene.emitters.empty() && MaxComponent(mat.baseColor) > 0.0f) {
      const Emitter& e = scene.emitters[PickEmitter(scene.emitters, ul.x)];
      const Triangle& light = scene.triangles[e.triangle];
      const Material& lm = scene.materials[light.material];
      vec2 b = SampleUniformTriangle(ul.y, ul.z);
      vec3 x = light.v0 + b.x * light.e1 + b.y * light.e2;
      vec3 nl = GeometricNormal(light);
      float w = LightSampleWeight(p, n, x, nl, (lm.flags & kMaterialDoubleSided) != 0u, e.pmf, e.area);
      if (w > 0.0f) {
        // Aim at the light point lifted off the emitter towards p, with tMax = 1 on the
        // unnormalised direction: the emitter itself then lies beyond tMax.
        vec3 target = OffsetRayOrigin(x, dot(nl, p - x) > 0.0f ? nl : -nl);
        ++stats.rays;
        if (!Occluded(scene.nodes, scene.triangles, origin, target - origin, 1.0f))
          radiance += throughput * brdf * lm.emission * w;
      }
    }

    // Cosine-weighted bounce: f·cos θ / pdf = (ρ/π)·cos θ / (cos θ/π) = ρ.
    throughput *= mat.baseColor;
    // Russian roulette (GAMES101: continue with probability P, divide by P): survival
    // follows the throughput, so dim paths end early and bright ones rarely.
    if (bounce >= params.rrDepth) {
      float survive = min(1.0f, MaxComponent(throughput));
      if (!(ul.w < survive)) break;
      throughput /= survive;
    }
    vec4 ub = rand(BsdfGroup(bounce));
    ray.origin = origin;
    ray.dir = FrameToWorld(FrameFromNormal(n), SampleCosineHemisphere(ub.x, ub.y));
  }
  return radiance;
}

CpuRenderResult RenderCpu(const RenderScene& scene, const FrameParams& params, const CpuRenderOptions& options) {
  CpuRenderResult result;
  result.image = Image(params.width, params.height);
  result.image.variance.assign(result.image.pixels.size(), glm::vec3(0.0f));
  unsigned threads = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  threads = std::min<unsigned>(threads, params.height);
  result.threads = threads;

  std::atomic<uint32_t> nextRow{0}, rowsDone{0};
  std::vector<SampleStats> perThread(threads);
  auto worker = [&](unsigned id) {
    SampleStats& st = perThread[id];
    for (uint32_t y; (y = nextRow.fetch_add(1)) < params.height;) {
      for (uint32_t x = 0; x < params.width; ++x) {
        glm::dvec3 sum(0.0), sumSq(0.0);
        for (uint32_t s = 0; s < params.sampleCount; ++s) {
          glm::vec3 L = SampleRadiance(scene, params, x, y, params.sampleBegin + s, st);
          if (!std::isfinite(L.x) || !std::isfinite(L.y) || !std::isfinite(L.z)) {
            ++st.nonFinite;
            continue;
          }
          sum += glm::dvec3(L);
          sumSq += glm::dvec3(L) * glm::dvec3(L);
        }
        const double n = params.sampleCount;
        glm::dvec3 mean = sum / n;
        size_t i = size_t(y) * params.width + x;
        result.image.pixels[i] = glm::vec3(mean);
        // Unbiased sample variance divided by n: the variance of the pixel mean.
        if (n > 1) result.image.variance[i] = glm::vec3(glm::max(sumSq / n - mean * mean, 0.0) / (n - 1.0));
      }
      rowsDone.fetch_add(1);
    }
  };

  auto t0 = std::chrono::steady_clock::now();
  std::vector<std::thread> pool;
  for (unsigned i = 1; i < threads; ++i) pool.emplace_back(worker, i);
  if (options.progress) {
    // The calling thread reports progress and then joins the work.
    std::thread w0(worker, 0u);
    while (rowsDone.load() < params.height) {
      options.progress(double(rowsDone.load()) / params.height);
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    w0.join();
    options.progress(1.0);
  } else {
    worker(0);
  }
  for (auto& t : pool) t.join();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const SampleStats& st : perThread) {
    result.stats.rays += st.rays;
    result.stats.nonFinite += st.nonFinite;
  }
  return result;
}

}  // namespace vkpt

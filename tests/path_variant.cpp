// One variant of the shared estimator for the CPU (see path_variants.h): compiled with
// VKPT_PATH_VARIANT=<the function's name>, VKPT_ESTIMATOR_OVERRIDES and the macros that
// select the variant's replacements (shaders/estimator_overrides.h).
//
// The headers that call the replaced seams (path.h, and through it the overrides,
// bsdf.h, microfacet.h and lights.h) are compiled here inside the namespace
// vkpt::shader::<variant>, so that their inline functions cannot stand in for the
// product's (one definition rule) nor the product's for them; everything else they use
// comes from vkpt::shader as in host/cpu/cpu_trace.h, included first. Only path.h includes
// bsdf.h and lights.h, and only bsdf.h microfacet.h, so none of the four is included before.
#include "path_variants.h"

#include <atomic>
#include <cmath>

#include "util/parallel.h"

#ifndef VKPT_PATH_VARIANT
#error "compile with VKPT_PATH_VARIANT=<function name> (tests/CMakeLists.txt)"
#endif

#include "cpu/cpu_trace.h"
#include "shared/environment.h"
#include "shared/estimator.h"
#include "shared/ggx_albedo.h"
#include "shared/intersect.h"
#include "shared/layout.h"
#include "shared/rng.h"
#include "shared/sampling.h"
#include "shared/shading_frame.h"

#undef VKPT_BEGIN_NAMESPACE
#undef VKPT_END_NAMESPACE
#define VKPT_BEGIN_NAMESPACE namespace vkpt::shader::VKPT_PATH_VARIANT {
#define VKPT_END_NAMESPACE }
#include "shared/path.h"  // and through it bsdf.h, microfacet.h and lights.h, also in the variant's namespace
#undef VKPT_BEGIN_NAMESPACE
#undef VKPT_END_NAMESPACE

namespace vkpt::internal::test {

RenderResult VKPT_PATH_VARIANT(const RenderScene& scene, const shader::FrameParams& params) {
  Film film(params.width, params.height);
  std::atomic<uint64_t> rays{0}, nonFinite{0};
  ParallelFor(params.height, ThreadCount(0), [&](size_t y) {
    uint64_t rowRays = 0, rowNonFinite = 0;
    for (uint32_t x = 0; x < params.width; ++x) {
      PixelSums sums;
      sums.samples = params.sampleCount;
      for (uint32_t s = 0; s < params.sampleCount; ++s) {
        shader::VKPT_PATH_VARIANT::PathSample p =
            shader::VKPT_PATH_VARIANT::TracePath(scene, params, x, uint32_t(y), params.sampleBegin + s);
        rowRays += p.rays;
        const glm::dvec3 L(p.radiance);
        if (!std::isfinite(L.x) || !std::isfinite(L.y) || !std::isfinite(L.z)) {
          ++rowNonFinite;
          continue;
        }
        sums.sum += L;
        sums.sumOfSquares += L * L;
      }
      film.SetPixel(y * params.width + x, sums);
    }
    rays.fetch_add(rowRays);
    nonFinite.fetch_add(rowNonFinite);
  });
  RenderResult r;
  r.image = film.TakeImage();
  r.rays = rays.load();
  r.nonFinite = nonFinite.load();
  return r;
}

}  // namespace vkpt::internal::test

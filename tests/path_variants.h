// The shared estimator (shaders/shared/path.h) recompiled for the CPU with test-only
// macros (tests/path_variant.cpp, built once per variant by tests/CMakeLists.txt): the
// two MIS strategies alone, and mutants that the MIS and light transport tests must
// reject. Each renders as RenderCpu does (same RNG streams, same Film), on all cores.
#pragma once

#include "render/film.h"
#include "render/render_scene.h"

// Sanitizer builds link stubs that abort (path_variant_stubs.cpp) instead of the 14 builds
// of the estimator: the tests that render a variant are statistics and skip there.
#if defined(VKPT_PATH_VARIANTS_STUBBED)
#define VKPT_REQUIRE_PATH_VARIANTS() \
  GTEST_SKIP() << "a statistic over the estimator's variants, which sanitizer builds do not compile"
#else
#define VKPT_REQUIRE_PATH_VARIANTS() static_cast<void>(0)
#endif

namespace vkpt::internal::test {

using PathVariantRenderer = RenderResult (*)(const RenderScene&, const shader::FrameParams&);

RenderResult RenderMisLightOnly(const RenderScene& scene, const shader::FrameParams& params);  // VKPT_MIS_LIGHT_ONLY
RenderResult RenderMisBsdfOnly(const RenderScene& scene, const shader::FrameParams& params);   // VKPT_MIS_BSDF_ONLY
// Mutants: MIS with both weights 1; MIS with the light sample's pdfs swapped; the GGX
// reflection pdf without its 1/(4 ωo·h), with MIS and with BSDF sampling alone.
RenderResult RenderMutantMisWeightOne(const RenderScene& scene, const shader::FrameParams& params);
RenderResult RenderMutantMisSwappedPdfs(const RenderScene& scene, const shader::FrameParams& params);
RenderResult RenderMutantNoJacobian(const RenderScene& scene, const shader::FrameParams& params);
RenderResult RenderMutantNoJacobianBsdfOnly(const RenderScene& scene, const shader::FrameParams& params);
// Mutants of the punctual lights (lights.h): the spot cone's falloff not squared; the range
// window squared; no 1/r²; a directional light's irradiance times an extra cos θ.
RenderResult RenderMutantSpotFalloffLinear(const RenderScene& scene, const shader::FrameParams& params);
RenderResult RenderMutantRangeWindowSquared(const RenderScene& scene, const shader::FrameParams& params);
RenderResult RenderMutantPointNoInverseSquare(const RenderScene& scene, const shader::FrameParams& params);
RenderResult RenderMutantDirectionalExtraCosine(const RenderScene& scene, const shader::FrameParams& params);
// Mutant of triangle lights (lights.h): a light sample's emission without the emissive texture.
RenderResult RenderMutantLightSampleWithoutTexture(const RenderScene& scene, const shader::FrameParams& params);
// And a light sample's emission not dimmed by the emitter's clear coat.
RenderResult RenderMutantLightSampleWithoutCoat(const RenderScene& scene, const shader::FrameParams& params);
// Mutant of texture filtering (path.h): every texture at its ray cone's level everywhere.
RenderResult RenderMutantTexturesFilteredEverywhere(const RenderScene& scene, const shader::FrameParams& params);
// Mutant of dispersion (path.h): the hero wavelength's weight applied at every dispersive vertex.
RenderResult RenderMutantWavelengthWeightEveryVertex(const RenderScene& scene, const shader::FrameParams& params);

}  // namespace vkpt::internal::test

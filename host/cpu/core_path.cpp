// The shared estimator (shaders/shared/path.h) once more, for scenes whose materials use
// none of the layered extensions — clear coat, sheen, diffuse transmission, iridescence,
// anisotropy, dispersion — which is most glTF files: the constants pathtrace.comp
// specializes on for them set false, so that the compiler drops their code from the BSDF
// and the path as lavapipe's does (bench/README.md measures what it saves).
//
// As in simple_path.cpp, the headers that read those constants are compiled here inside
// the namespace vkpt::shader::core, so that their inline functions cannot stand in for
// the general ones (one definition rule), and everything else comes from vkpt::shader as
// in cpu_trace.h; the environment is the general one. Only path.h includes them, so none is
// included before.
#include "cpu/cpu_trace.h"
#include "cpu/path_tracer.h"
#include "shared/environment.h"
#include "shared/estimator.h"
#include "shared/fresnel.h"
#include "shared/ggx_albedo.h"
#include "shared/intersect.h"
#include "shared/layout.h"
#include "shared/normal_map.h"
#include "shared/ray_cone.h"
#include "shared/rng.h"
#include "shared/sampling.h"
#include "shared/shading_normal.h"
#include "shared/texture.h"
#include "shared/vertex_color.h"

#define VKPT_CLEARCOAT false
#define VKPT_SHEEN false
#define VKPT_DIFFUSE_TRANSMISSION false
#define VKPT_IRIDESCENCE false
#define VKPT_ANISOTROPY false
#define VKPT_DISPERSION false
#undef VKPT_BEGIN_NAMESPACE
#undef VKPT_END_NAMESPACE
#define VKPT_BEGIN_NAMESPACE namespace vkpt::shader::core {
#define VKPT_END_NAMESPACE }
#include "shared/path.h"  // and through it bsdf.h, lights.h, shading_frame.h and the lobes'
#undef VKPT_BEGIN_NAMESPACE
#undef VKPT_END_NAMESPACE

namespace vkpt::internal {

bool IsCoreScene(const RenderScene& scene) {
  return !UsesClearcoat(scene) && !UsesSheen(scene) && !UsesDiffuseTransmission(scene) && !UsesIridescence(scene) &&
         !UsesAnisotropy(scene) && !UsesDispersion(scene);
}

glm::vec3 SampleRadianceCore(const RenderScene& scene, const shader::FrameParams& params, uint32_t px, uint32_t py,
                             uint32_t sampleIndex, SampleStats& stats) {
  return CountRays(shader::core::TracePath(scene, params, px, py, sampleIndex), stats);
}

}  // namespace vkpt::internal

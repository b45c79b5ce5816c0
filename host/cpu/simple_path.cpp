// The shared estimator (shaders/shared/path.h) once more, for simple scenes: the
// constants pathtrace.comp specializes on, set to what IsSimpleScene requires, let the
// compiler drop the code such a scene never runs (the GGX lobes, vertex normals and
// colours, the other light types, the environment map) and keep in registers what the general
// estimator spills (docs/design-notes.md, the Cornell box's cost of the glTF BSDF).
//
// The headers that read those constants are compiled here inside the namespace
// vkpt::shader::simple, so that their inline functions cannot stand in for the general
// ones (one definition rule); everything else comes from vkpt::shader as in cpu_trace.h.
// Only path.h includes them, so none is included before.
#include "cpu/cpu_trace.h"
#include "cpu/path_tracer.h"
#include "shared/estimator.h"
#include "shared/ggx_albedo.h"
#include "shared/intersect.h"
#include "shared/layout.h"
#include "shared/microfacet.h"
#include "shared/rng.h"
#include "shared/sampling.h"
#include "shared/transmission.h"

#define VKPT_LIGHT_TYPES ((1u << kLightTriangle) | (1u << kLightTwoSidedTriangle))
#define VKPT_GLOSSY_MATERIALS false
#define VKPT_SMOOTH_NORMALS false
#define VKPT_ENVIRONMENT_MAP false
#undef VKPT_VERTEX_COLORS
#define VKPT_VERTEX_COLORS false
#define VKPT_VOLUMES false
#define VKPT_CLEARCOAT false
#define VKPT_SHEEN false
#define VKPT_DIFFUSE_TRANSMISSION false
#define VKPT_IRIDESCENCE false
#undef VKPT_ANISOTROPY
#define VKPT_ANISOTROPY false
#define VKPT_DISPERSION false
#undef VKPT_TEXTURES
#define VKPT_TEXTURES false
#undef VKPT_NORMAL_MAPS
#define VKPT_NORMAL_MAPS false
#undef VKPT_ALPHA
#define VKPT_ALPHA ((void)scene, false)  // read, so that path.h's RayAlphaKey uses its scene parameter
#undef VKPT_BEGIN_NAMESPACE
#undef VKPT_END_NAMESPACE
#define VKPT_BEGIN_NAMESPACE namespace vkpt::shader::simple {
#define VKPT_END_NAMESPACE }
#include "shared/path.h"  // and through it environment.h, lights.h, shading_frame.h and bsdf.h
#undef VKPT_BEGIN_NAMESPACE
#undef VKPT_END_NAMESPACE

namespace vkpt::internal {

bool IsSimpleScene(const RenderScene& scene, const shader::FrameParams& params) {
  for (const shader::Light& l : scene.lights)
    if (((1u << l.type) & shader::simple::kTriangleLightTypes) == 0u) return false;
  for (const shader::TriangleShading& s : scene.shading)
    if ((s.flags & shader::kShadingHasNormals) != 0u) return false;
  return params.envWidth == 0u && scene.vertexColors.empty() && scene.textureRefs.empty() && !scene.alphaTested &&
         !UsesGlossyMaterial(scene) && !UsesVolumeMaterial(scene);
}

glm::vec3 SampleRadianceSimple(const RenderScene& scene, const shader::FrameParams& params, uint32_t px, uint32_t py,
                               uint32_t sampleIndex, SampleStats& stats) {
  return CountRays(shader::simple::TracePath(scene, params, px, py, sampleIndex), stats);
}

}  // namespace vkpt::internal

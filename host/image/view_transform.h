// View transforms: scene-linear Rec.709 radiance → display-linear Rec.709 in [0, 1], the
// picture an 8-bit sRGB file shows. Only PNG output goes through one; EXR and PFM stay
// linear and untouched.
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>

namespace vkpt::internal {

enum class View {
  kClamp,    // radiance clipped to [0, 1]: bright highlights burn to white
  kNeutral,  // Khronos PBR Neutral (KhronosGroup/ToneMapping, PBR_Neutral/README.md)
  kAgx,      // Blender's "AgX" view, look None (AgX Base, Rec.2020 working space)
  kAces,     // Stephen Hill's fit of ACES 1.0 RRT + sRGB ODT (BakingLab ACES.hlsl)
};

// "clamp", "neutral", "agx", "aces".
const char* ViewName(View view);
std::optional<View> ViewFromName(const std::string& name);

// How radiance becomes a displayed value: × 2^exposure, then the view.
struct DisplayTransform {
  View view = View::kClamp;
  float exposure = 0.0f;  // stops

  // Display-linear RGB in [0, 1]. NaN and negative radiance show as 0 and +Inf as the
  // view's white, so a stray sample never turns a pixel into an artefact of the curve.
  glm::vec3 Apply(glm::vec3 radiance) const;
};

// The curves on sanitised input (finite, ≥ 0), in double so that their published reference
// values can be checked to the digits they are given with.
glm::dvec3 PbrNeutral(glm::dvec3 c);
glm::dvec3 AgxBase(glm::dvec3 c);
glm::dvec3 AcesFitted(glm::dvec3 c);

}  // namespace vkpt::internal

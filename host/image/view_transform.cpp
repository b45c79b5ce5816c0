#include "image/view_transform.h"

#include <algorithm>
#include <cmath>

namespace vkpt::internal {
namespace {

// Radiance above half-float's largest value is far into every curve's white (PBR Neutral
// gives 0.9999991 at 65504); capping it keeps +Inf from becoming Inf·0 = NaN inside a curve.
constexpr double kLargest = 65504.0;

double Sanitise(float x) { return std::isnan(x) || x <= 0.0f ? 0.0 : std::min(double(x), kLargest); }

}  // namespace

const char* ViewName(View view) {
  switch (view) {
    case View::kClamp: return "clamp";
    case View::kNeutral: return "neutral";
    case View::kAgx: return "agx";
    case View::kAces: return "aces";
  }
  return "clamp";
}

std::optional<View> ViewFromName(const std::string& name) {
  for (View v : {View::kClamp, View::kNeutral, View::kAgx, View::kAces})
    if (name == ViewName(v)) return v;
  return std::nullopt;
}

glm::vec3 DisplayTransform::Apply(glm::vec3 radiance) const {
  const glm::vec3 exposed = radiance * std::exp2(exposure);
  if (view == View::kClamp) {
    glm::vec3 out;
    for (int i = 0; i < 3; ++i) out[i] = std::isnan(exposed[i]) ? 0.0f : std::clamp(exposed[i], 0.0f, 1.0f);
    return out;
  }
  const glm::dvec3 c(Sanitise(exposed.r), Sanitise(exposed.g), Sanitise(exposed.b));
  const glm::dvec3 d = view == View::kNeutral ? PbrNeutral(c) : view == View::kAgx ? AgxBase(c) : AcesFitted(c);
  return glm::vec3(glm::clamp(d, 0.0, 1.0));
}

// Khronos PBR Neutral, as its specification writes it (PBR_Neutral/README.md and
// pbrNeutral.glsl, KhronosGroup/ToneMapping): colours below 0.8 keep their values less a
// small Fresnel offset; above, the peak is compressed and the colour desaturated towards it,
// with no hue shift.
glm::dvec3 PbrNeutral(glm::dvec3 c) {
  constexpr double kStartCompression = 0.8 - 0.04;
  constexpr double kDesaturation = 0.15;
  const double x = std::min(c.r, std::min(c.g, c.b));
  const double offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
  c -= offset;
  const double peak = std::max(c.r, std::max(c.g, c.b));
  if (peak < kStartCompression) return c;
  constexpr double d = 1.0 - kStartCompression;
  const double newPeak = 1.0 - d * d / (peak + d - kStartCompression);
  c *= newPeak / peak;
  const double g = 1.0 - 1.0 / (kDesaturation * (peak - newPeak) + 1.0);
  return glm::mix(c, glm::dvec3(newPeak), g);
}

// Stephen Hill's fit of the ACES 1.0 reference rendering and sRGB output transforms
// (TheRealMJP/BakingLab, ACES.hlsl, MIT): sRGB → ACEScg with the RRT's saturation, a
// rational fit of the RRT+ODT tone scale per channel, then back to sRGB with the ODT's
// saturation. Not the full ACES pipeline (no glow or red modifier), and without the 1/0.6
// pre-exposure some engines add: 0.18 shows as ACES shows it, about 0.106.
glm::dvec3 AcesFitted(glm::dvec3 c) {
  // Row-major as published; glm is column-major, hence the transposes.
  const glm::dmat3 input =
      glm::transpose(glm::dmat3(0.59719, 0.35458, 0.04823, 0.07600, 0.90834, 0.01566, 0.02840, 0.13383, 0.83777));
  const glm::dmat3 output =
      glm::transpose(glm::dmat3(1.60475, -0.53108, -0.07367, -0.10208, 1.10813, -0.00605, -0.00327, -0.07276, 1.07602));
  const glm::dvec3 v = input * c;
  const glm::dvec3 fit = (v * (v + 0.0245786) - 0.000090537) / (v * (0.983729 * v + 0.4329510) + 0.238081);
  return glm::clamp(output * fit, 0.0, 1.0);
}

}  // namespace vkpt::internal

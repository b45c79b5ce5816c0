// Blender's "AgX" view (look None), computed instead of read from its 57³ LUT.
//
// Blender (4.0 and later) ships AgX as an OCIO LUT, AgX_Base_sRGB.cube, baked by Eary Chow's
// generator (EaryChow/AgX_LUT_Gen, AgXBasesRGB.py) from Troy Sobotka's AgX: Rec.709 → Rec.2020,
// an "inset" matrix that pulls primaries inwards, a log2 encoding of −10..+6.5 stops around
// 0.18, Sobotka's two-part sigmoid, 40 % of the hue shifts the per-channel curve made undone,
// the "outset" matrix, back to Rec.709 and a luminance-preserving guard against negative
// channels. This chain reproduces the shipped LUT to 1.6e-6 (its file has 7 decimals) with the
// luminance coefficients the LUT was baked with; the LUT's own tetrahedral interpolation
// differs from it by at most 0.024 in display-linear values.
#include <algorithm>
#include <cmath>

#include "image/view_transform.h"

namespace vkpt::internal {
namespace {

// Row-major as published; glm is column-major, hence the transposes.
glm::dmat3 RowMajor(double a, double b, double c, double d, double e, double f, double g, double h, double i) {
  return glm::transpose(glm::dmat3(a, b, c, d, e, f, g, h, i));
}

const glm::dmat3 kRec709ToRec2020 = RowMajor(0.6274019247, 0.3292919718, 0.0433061035, 0.0690954897, 0.9195442813,
                                             0.0113602290, 0.0163937091, 0.0880281624, 0.8955781285);
const glm::dmat3 kRec2020ToRec709 = RowMajor(1.6604962191, -0.5876564441, -0.0728397750, -0.1245470956, 1.1328951092,
                                             -0.0083480137, -0.0181536814, -0.1005973717, 1.1187510531);
const glm::dmat3 kInset =
    RowMajor(0.856627153315983, 0.0951212405381588, 0.0482516061458583, 0.137318972929847, 0.761241990602591,
             0.101439036467562, 0.11189821299995, 0.0767994186031903, 0.811302368396859);
const glm::dmat3 kOutset =
    glm::inverse(RowMajor(0.899796955911611, 0.0871996192028351, 0.013003424885555, 0.11142098895748, 0.875575586156966,
                          0.0130034248855548, 0.11142098895748, 0.0871996192028349, 0.801379391839686));

// Sobotka's sigmoid (SB2383, sigmoid.py): two power curves meeting at the pivot (x 10/16.5,
// the log position of 0.18; y 0.18^(1/2.4)) with slope 2.4, through (0, 0) and (1, 1).
double Sigmoid(double x) {
  constexpr double kSlope = 2.4, kPower = 1.5, kPivotX = 10.0 / 16.5;
  static const double kPivotY = std::pow(0.18, 1.0 / 2.4);
  static const double kToe = -std::pow(
      std::pow(kSlope * kPivotX, -kPower) * (std::pow(kSlope * kPivotX / kPivotY, kPower) - 1.0), -1.0 / kPower);
  static const double kShoulder = std::pow(std::pow(kSlope * (1.0 - kPivotX), -kPower) *
                                               (std::pow(kSlope * (1.0 - kPivotX) / (1.0 - kPivotY), kPower) - 1.0),
                                           -1.0 / kPower);
  const double k = x < kPivotX ? kToe : kShoulder;
  const double t = kSlope * (x - kPivotX) / k;
  return kPivotY + k * t / std::pow(1.0 + std::pow(t, kPower), 1.0 / kPower);
}

// Hue of Smith's HSV as colour-science computes it (blue wins a tie with green, green with red).
double Hue(glm::dvec3 c) {
  const double mx = std::max(c.r, std::max(c.g, c.b)), mn = std::min(c.r, std::min(c.g, c.b)), d = mx - mn;
  if (d == 0.0) return 0.0;
  const glm::dvec3 delta = ((mx - c) / 6.0 + d / 2.0) / d;
  double h = 0.0;
  if (c.r == mx) h = delta.b - delta.g;
  if (c.g == mx) h = 1.0 / 3.0 + delta.r - delta.b;
  if (c.b == mx) h = 2.0 / 3.0 + delta.g - delta.r;
  return h < 0.0 ? h + 1.0 : h > 1.0 ? h - 1.0 : h;
}

// `c` with its HSV hue replaced by `hue`, value and saturation kept.
glm::dvec3 WithHue(glm::dvec3 c, double hue) {
  const double v = std::max(c.r, std::max(c.g, c.b)), mn = std::min(c.r, std::min(c.g, c.b));
  const double s = v == 0.0 ? 0.0 : (v - mn) / v;
  double h = hue * 6.0;
  if (h == 6.0) h = 0.0;
  const double i = std::floor(h), f = h - i;
  const double p = v * (1.0 - s), q = v * (1.0 - s * f), t = v * (1.0 - s * (1.0 - f));
  switch (int(i)) {
    case 0: return {v, t, p};
    case 1: return {q, v, p};
    case 2: return {p, v, t};
    case 3: return {p, q, v};
    case 4: return {t, p, v};
    default: return {v, p, q};
  }
}

// From hue `from` a fraction `t` of the way to hue `to`, the short way round the circle.
double MixHue(double from, double to, double t) {
  if (to - from > 0.5) to -= 1.0;
  else if (to - from < -0.5) to += 1.0;
  const double h = from + t * (to - from);
  return h - std::floor(h);
}

// Luminance of a Rec.709 colour, with the Rec.2020 weights the shipped LUT was baked with.
double Luminance(glm::dvec3 c709) {
  return glm::dot(kRec709ToRec2020 * c709, glm::dvec3(0.2658180370250449, 0.59846986045365, 0.1357121025213052));
}

// A luminance that stays meaningful for colours with a negative channel: towards black it
// blends into "chroma minus the luminance of the complement", which is positive there.
double CompensatedLuminance(glm::dvec3 c) {
  const double mx = std::max(c.r, std::max(c.g, c.b)), mn = std::min(c.r, std::min(c.g, c.b));
  const double y = Luminance(c);
  const double compensated = (mx - mn) - Luminance(mx - c) + y;
  return glm::mix(compensated, y, std::clamp(std::pow(std::max(y, 0.0), 0.08), 0.0, 1.0));
}

// Lifts a colour with negative channels into gamut by adding grey, then scales it back to the
// luminance it had (luminance_compenstation_srgb.py).
glm::dvec3 GamutGuard(glm::dvec3 c) {
  const double y = CompensatedLuminance(c);
  const glm::dvec3 lifted = c + std::max(-std::min(c.r, std::min(c.g, c.b)), 0.0);
  const double yLifted = CompensatedLuminance(lifted);
  return yLifted > y ? lifted * (y / std::max(yLifted, 1e-100)) : lifted;
}

}  // namespace

glm::dvec3 AgxBase(glm::dvec3 c) {
  c = kInset * (kRec709ToRec2020 * c);
  const double hue = Hue(c);
  glm::dvec3 y;
  for (int i = 0; i < 3; ++i) {
    const double stops = std::log2(std::max(c[i], 1e-10) / 0.18);
    y[i] = std::pow(std::max(Sigmoid((stops + 10.0) / 16.5), 0.0), 2.4);
  }
  y = WithHue(y, MixHue(hue, Hue(y), 0.4));
  return glm::clamp(GamutGuard(kRec2020ToRec709 * (kOutset * y)), 0.0, 1.0);
}

}  // namespace vkpt::internal

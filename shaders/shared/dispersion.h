// KHR_materials_dispersion: a volume's index of refraction that varies with wavelength,
// carried by a renderer that otherwise works in RGB.
//
// The index: the extension's two-term Cauchy equation n(λ) = A + B/λ², fitted so that
// n(λd) is the material's ior and (nd − 1)/(nF − nC) its Abbe number Vd (stored as
// 20/Vd), at the Fraunhofer lines d, F and C the extension names. Written here through the
// lines themselves rather than the extension's rounded constants (523655 nm², 1.5168),
// so that both hold to float precision; the rounded form spreads the index 4e-4 wider.
//
// The wavelength: a path draws one, the hero wavelength, at its first dispersive vertex,
// and keeps it (path.h): every later dispersive vertex refracts by the index at that
// wavelength, so the colours a prism separates stay separated along the path. The
// throughput is weighted by the wavelength's colour (SampleWavelength), which averages to
// white over the wavelengths, so a path that meets no dispersion on the way, or whose
// dispersion is 0, is unchanged, and a path through dispersive glass is white on average.
// (Wilkie et al. 2014 carry four wavelengths from the camera in a spectral renderer; an
// RGB renderer has one colour per path until the first dispersive event, so one
// wavelength drawn there is what it can carry.)
#ifndef VKPT_DISPERSION_H
#define VKPT_DISPERSION_H
#include "prelude.h"  // first, as in every shared header

#include "layout.h"

#ifdef __cplusplus
#include "albedo_tables.h"
#endif

// A shader may define VKPT_DISPERSION as a specialization constant that is false when no
// material is dispersive, so that lavapipe compiles no wavelength code for such scenes.
#ifndef VKPT_DISPERSION
#define VKPT_DISPERSION true
#endif

VKPT_BEGIN_NAMESPACE

// The Fraunhofer lines of the Abbe number, in nm: d (helium yellow), F (hydrogen blue)
// and C (hydrogen red), as the extension gives them.
const float kLineD = 587.6f;
const float kLineF = 486.1f;
const float kLineC = 656.3f;

// Cauchy's 1/λ² term relative to its value at λd, over the same at F less at C:
// 0 at λd, and 1 further at F than at C.
VKPT_FN float CauchySpread(float nm) {
  float d = kLineD / nm;
  const float dF = kLineD / kLineF, dC = kLineD / kLineC;
  return (d * d - 1.0f) / (dF * dF - dC * dC);
}

// The index at wavelength `nm` of a material of index `ior` (at λd) and dispersion 20/Vd,
// never below 1 (the extension's clamp, reached only far beyond realistic dispersion).
VKPT_FN float DispersiveIor(float ior, float dispersion, float nm) {
  return max(ior + (ior - 1.0f) * (dispersion / 20.0f) * CauchySpread(nm), 1.0f);
}

// A wavelength for `u` in [0, 1), in nm, and its colour weight: (λ, R, G, B). The bins
// of scripts/make_wavelength_table.cpp hold equal shares of the mean colour response
// (the CIE 1931 matching functions in linear Rec. 709, negative lobes clipped, each
// channel integrating to 1), λ is uniform within its bin, and the weight is the bin's
// colour over its probability: its channels sum to 3, and each averages to 1 over u, so a
// flat spectrum stays white. A bin is picked by one multiplication, not a search.
VKPT_FN vec4 SampleWavelength(float u) {
  float x = u * float(kWavelengthBins);
  uint k = uint(clamp(int(x), 0, int(kWavelengthBins) - 1));
  uint pair = kWavelengthOffset + 2u * k;
  vec2 startAndRed = VKPT_ALBEDO_PAIR(pair);
  vec2 greenAndBlue = VKPT_ALBEDO_PAIR(pair + 1u);
  float end = VKPT_ALBEDO_PAIR(pair + 2u).x;
  return vec4(mix(startAndRed.x, end, x - float(k)), startAndRed.y, greenAndBlue);
}

VKPT_END_NAMESPACE

#endif

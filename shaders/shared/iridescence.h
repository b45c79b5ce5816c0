// KHR_materials_iridescence: a thin dielectric film (index filmIor, thickness d in nm) on
// the material, whose reflectance F_film replaces Fresnel's in the metal and in the
// dielectric layer as the extension mixes them, F = mix(F, F_film, iridescence).
//
// F_film is Belcour & Barla 2017, "A Practical Extension to Microfacet Theory for the
// Modeling of Varying Iridescence": the Airy sum of the film's inter-reflections
// expanded as a Fourier series in the phase 2π OPD / λ (OPD = 2 filmIor d cos θ2), its
// terms integrated against the CIE 1931 matching functions in closed form by their
// Gaussian fit (FilmSensitivityXyz), then taken to linear Rec. 709 and balanced to its
// white (kFilmWhite). The extension's notes keep the first three terms; here they are
// summed until they vanish, at little cost by recurrences. The outside
// is air; the base's index comes from its F0 ((1 + √F0) / (1 − √F0), real for metals too),
// and each interface's phase shift is 0 or π by which side is denser, as the extension's
// implementation notes take them.
//
// The interfaces' reflectances are Fresnel's exact (unpolarised) ones, as in Belcour &
// Barla's reference code, where the extension's notes use Schlick's: a film of the base's
// own index then reflects exactly the base's Fresnel (tested), and a vanishing film does
// too at normal incidence (at oblique incidence the two interfaces' unpolarised
// reflectances do not add up to the base's, as their polarised amplitudes would). A film
// of thickness 0 is no film (the plain material, bit for bit).
#ifndef VKPT_IRIDESCENCE_H
#define VKPT_IRIDESCENCE_H
#include "prelude.h"  // first, as in every shared header

#include "sampling.h"

// A shader may define VKPT_IRIDESCENCE as a specialization constant that is false when no
// material is iridescent, so that lavapipe compiles no film for such scenes.
#ifndef VKPT_IRIDESCENCE
#define VKPT_IRIDESCENCE true
#endif

VKPT_BEGIN_NAMESPACE

// Fresnel's unpolarised reflectance of the boundary from index n1 to n2 at cos θ1 on
// n1's side; 1 under total internal reflection.
VKPT_FN float FresnelDielectric(float cosTheta1, float n1, float n2) {
  float eta = n1 / n2;
  float sin2T = eta * eta * max(1.0f - cosTheta1 * cosTheta1, 0.0f);
  if (sin2T >= 1.0f) return 1.0f;
  float cosT = sqrt(1.0f - sin2T);
  float rs = (n1 * cosTheta1 - n2 * cosT) / (n1 * cosTheta1 + n2 * cosT);
  float rp = (n2 * cosTheta1 - n1 * cosT) / (n2 * cosTheta1 + n1 * cosT);
  return 0.5f * (rs * rs + rp * rp);
}

// The index whose boundary with air reflects F0 at normal incidence (below 1 − 1e-4, so
// a white metal stays finite).
VKPT_FN float IorFromF0(float f0) {
  float s = sqrt(min(f0, 0.9999f));
  return (1.0f + s) / (1.0f - s);
}

// Belcour & Barla's fit of the CIE 1931 2° matching functions (x̄, ȳ, z̄) by Gaussians in
// frequency (x̄ two), each with its integral over ∫ ȳ dλ, its centre (m⁻¹) and variance:
// x̄'s main lobe, ȳ, z̄, x̄'s blue lobe.
const vec4 kFitAmplitude = vec4(0.84659000f, 1.0002219f, 1.0011225f, 0.15386831f);
const vec4 kFitCentre = vec4(1.6810e+06f, 1.7953e+06f, 2.2084e+06f, 2.2399e+06f);
const vec4 kFitVariance = vec4(4.3278e+09f, 9.3046e+09f, 6.6121e+09f, 4.5282e+09f);

VKPT_FN vec3 FitToXyz(vec4 g) { return vec3(g.x + g.w, g.y, g.z); }

// ∫ cmf(λ) cos(2π opd / λ + shift) dλ / ∫ ȳ(λ) dλ from the fit; opd in nm. Checked
// against a 1 nm integration of the CIE table in the tests.
VKPT_FN vec3 FilmSensitivityXyz(float opd, float shift) {
  float phase = 2.0f * kPi * opd * 1e-9f;
  return FitToXyz(kFitAmplitude * cos(kFitCentre * phase + shift) * exp(-phase * phase * kFitVariance));
}

// CIE XYZ to linear Rec. 709 (the renderer's colours), by rows.
VKPT_FN vec3 XyzToRec709(vec3 xyz) {
  return vec3(dot(vec3(3.2404542f, -1.5371385f, -0.4985314f), xyz), dot(vec3(-0.9692660f, 1.8760108f, 0.0415560f), xyz),
              dot(vec3(0.0556434f, -0.2040259f, 1.0572252f), xyz));
}

// Rec. 709 of the fit's equal-energy white (a spectrally flat reflectance of 1): the
// sensitivities are divided by it, so the series' constant term, which stands for such a
// flat spectrum, and its oscillating terms are in one balance, and a vanishing film
// reflects the base's Fresnel in every channel. (Taken to Rec. 709 without it, as the
// extension's notes do, a flat spectrum comes out (1.21, 0.95, 0.91).)
const vec3 kFilmWhite = vec3(1.2053688f, 0.9483195f, 0.9100097f);

// The series' terms are summed until they fall below this (or kFilmTerms of them): the
// extension's notes stop at two, which near grazing angles on a metal, where both
// interfaces reflect strongly, misses up to 0.14 of the reflectance.
const float kFilmTermFloor = 1e-4f;
const int kFilmTerms = 32;

// The film's reflectance at cos θ1 to its normal, from air, on a base of normal-incidence
// reflectance baseF0 (per channel); thickness in nm.
VKPT_RARE_FN vec3 ThinFilmFresnel(float cosTheta1, float filmIor, float thickness, vec3 baseF0) {
  float sin2Film = (1.0f - cosTheta1 * cosTheta1) / (filmIor * filmIor);
  if (sin2Film >= 1.0f) return vec3(1.0f);  // a film less dense than air reflects totally
  float cosTheta2 = sqrt(1.0f - sin2Film);
  float r12 = FresnelDielectric(cosTheta1, 1.0f, filmIor);
  float t121 = 1.0f - r12;
  vec3 baseIor = vec3(IorFromF0(baseF0.x), IorFromF0(baseF0.y), IorFromF0(baseF0.z));
  vec3 r23 = vec3(FresnelDielectric(cosTheta2, filmIor, baseIor.x), FresnelDielectric(cosTheta2, filmIor, baseIor.y),
                  FresnelDielectric(cosTheta2, filmIor, baseIor.z));
  // Phase shifts on reflection, as the extension's notes take them: φ21 = π inside the
  // film at its top, and φ23 = π at its bottom where the base is less dense (the other
  // convention flips both, and their sum is the same modulo 2π). Term m shifts by m φ:
  // φ21 in the cosines, φ23 as the sign (−1)^m of a channel's coefficient.
  float phi21 = filmIor < 1.0f ? 0.0f : kPi;
  vec3 flip =
      vec3(baseIor.x < filmIor ? -1.0f : 1.0f, baseIor.y < filmIor ? -1.0f : 1.0f, baseIor.z < filmIor ? -1.0f : 1.0f);
  vec3 r123 = clamp(r12 * r23, vec3(0.0f), vec3(0.9999f));
  vec3 rs = (t121 * t121) * r23 / (vec3(1.0f) - r123);
  vec3 reflectance = vec3(r12) + rs;  // the series' constant term
  vec3 cm = rs - vec3(t121);
  vec3 step = sqrt(r123) * flip;
  // Term m integrates cos(m (2π OPD / λ + φ21)) against each Gaussian of the fit:
  // cos(m θ) exp(−m² q), by the recurrences cos(m θ) = 2 cos θ cos((m − 1) θ) −
  // cos((m − 2) θ) and exp(−m² q) = exp(−(m − 1)² q) exp(−q)^(2m − 1).
  float phase = 2.0f * kPi * (2.0f * filmIor * thickness * cosTheta2) * 1e-9f;
  vec4 cos1 = cos(kFitCentre * phase + phi21), cosPrev = vec4(1.0f), cosM = cos1;
  vec4 w = exp(-phase * phase * kFitVariance), ratio = w, gauss = w;
  for (int m = 1; m <= kFilmTerms; ++m) {
    cm *= step;
    vec3 sensitivity = XyzToRec709(FitToXyz(kFitAmplitude * cosM * gauss)) / kFilmWhite;
    reflectance += cm * (2.0f * sensitivity);
    if (MaxComponent(abs(cm)) < kFilmTermFloor) break;
    vec4 cosNext = 2.0f * cos1 * cosM - cosPrev;
    cosPrev = cosM;
    cosM = cosNext;
    ratio *= w * w;
    gauss *= ratio;
  }
  // Out-of-gamut spectra leave Rec. 709: kept a reflectance, so 1 − F stays transmittance.
  return clamp(reflectance, vec3(0.0f), vec3(1.0f));
}

VKPT_END_NAMESPACE

#endif

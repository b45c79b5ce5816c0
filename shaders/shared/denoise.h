// vkpt's denoiser: the edge-avoiding à-trous wavelet filter (Dammertz, Sewtz, Hanika and
// Lensch 2010, "Edge-Avoiding À-Trous Wavelet Transform for fast Global Illumination
// Filtering") with the luminance weights of SVGF (Schied et al. 2017, "Spatiotemporal
// Variance-Guided Filtering"), one source for the CPU and the GPU (denoise.comp).
//
// The filter runs on the image divided by its albedo AOV (demodulated: the lighting,
// smooth where textures are not) and the host multiplies the albedo back. Iteration i
// spreads the 5 × 5 B3-spline kernel over taps 2^i pixels apart; each tap's weight is the
// kernel's times
//   normal     max(0, n_p · n_q)^kSigmaNormal (1 where both have no surface, 0 where one has)
//   depth      exp(−|z_p − z_q| / (kSigmaDepth · step · max(z_p, z_q) + ε)): relative, so
//              that a slanted plane's depth change over the step still passes
//   albedo     exp(−|a_p − a_q|² / kSigmaAlbedo²): a hard edge between two albedos stays
//   luminance  exp(−|l_p − l_q| / (kSigmaLuminance · σ_p + ε)), σ_p the standard deviation
//              of pixel p's luminance as estimated from its samples (and carried through
//              the iterations: Var = Σ w² Var_q / (Σ w)², SVGF eq. 4)
// so the filter averages only what its guides say is the same surface and what the noise
// says could differ by chance. The centre tap always has weight > 0.
//
// The including side supplies, for pixel i (row-major):
//   VKPT_DENOISE_COLOR(i)    vec4: demodulated RGB, variance of its luminance
//   VKPT_DENOISE_GUIDE(i)    vec4: normal (0: no surface), depth
//   VKPT_DENOISE_ALBEDO(i)   vec3: albedo
//   VKPT_DENOISE_PARAM / VKPT_DENOISE_ARG   a leading parameter and argument ("" in GLSL)
#ifndef VKPT_DENOISE_H
#define VKPT_DENOISE_H
#include "layout.h"
#include "prelude.h"

VKPT_BEGIN_NAMESPACE

const float kSigmaNormal = 64.0f;
const float kSigmaDepth = 0.02f;
const float kSigmaAlbedo = 0.1f;
const float kSigmaLuminance = 4.0f;

VKPT_FN float DenoiseLuminance(vec3 c) { return dot(c, vec3(0.2126f, 0.7152f, 0.0722f)); }

// The B3-spline kernel (1, 4, 6, 4, 1) / 16 at offset k ∈ [−2, 2].
VKPT_FN float B3(int k) {
  int a = abs(k);
  return a == 0 ? 0.375f : (a == 1 ? 0.25f : 0.0625f);
}

VKPT_FN float NormalWeight(vec3 np, vec3 nq) {
  bool surfaceP = dot(np, np) > 0.0f, surfaceQ = dot(nq, nq) > 0.0f;
  if (!surfaceP || !surfaceQ) return surfaceP == surfaceQ ? 1.0f : 0.0f;
  return pow(max(0.0f, dot(normalize(np), normalize(nq))), kSigmaNormal);
}

// Pixel (x, y) of iteration `iteration` over a width × height image.
VKPT_FN vec4 AtrousPixel(VKPT_DENOISE_PARAM uint width, uint height, uint x, uint y, uint iteration) {
  uint p = y * width + x;
  vec4 cp = VKPT_DENOISE_COLOR(p);
  vec4 gp = VKPT_DENOISE_GUIDE(p);
  vec3 ap = VKPT_DENOISE_ALBEDO(p);
  float lp = DenoiseLuminance(vec3(cp));
  float sigmaL = kSigmaLuminance * sqrt(max(cp.w, 0.0f)) + 1e-6f;
  int step = 1 << int(iteration);
  vec3 sum = vec3(0.0f);
  float weights = 0.0f;
  float variance = 0.0f;
  for (int dy = -2; dy <= 2; ++dy) {
    for (int dx = -2; dx <= 2; ++dx) {
      int qx = int(x) + dx * step, qy = int(y) + dy * step;
      if (qx < 0 || qy < 0 || qx >= int(width) || qy >= int(height)) continue;
      uint q = uint(qy) * width + uint(qx);
      vec4 cq = VKPT_DENOISE_COLOR(q);
      vec4 gq = VKPT_DENOISE_GUIDE(q);
      vec3 da = ap - VKPT_DENOISE_ALBEDO(q);
      float depthScale = kSigmaDepth * float(step) * max(gp.w, gq.w) + 1e-6f;
      float w = B3(dx) * B3(dy) * NormalWeight(vec3(gp), vec3(gq)) * exp(-abs(gp.w - gq.w) / depthScale) *
                exp(-dot(da, da) / (kSigmaAlbedo * kSigmaAlbedo)) * exp(-abs(lp - DenoiseLuminance(vec3(cq))) / sigmaL);
      sum += w * vec3(cq);
      weights += w;
      variance += w * w * cq.w;
    }
  }
  return vec4(sum / weights, variance / (weights * weights));
}

VKPT_END_NAMESPACE

#endif

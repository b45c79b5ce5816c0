#version 460
// One iteration of vkpt's à-trous denoiser (shared/denoise.h, the code the CPU runs): one
// invocation per pixel, from one buffer of colours to the other.
#extension GL_GOOGLE_include_directive : require

#include "shared/layout.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = kBindingDenoiseColor) readonly buffer Color { vec4 colorIn[]; };
layout(std430, binding = kBindingDenoiseGuide) readonly buffer Guide { vec4 guide[]; };
layout(std430, binding = kBindingDenoiseAlbedo) readonly buffer Albedo { vec4 albedo[]; };
layout(std430, binding = kBindingDenoiseOut) writeonly buffer Out { vec4 colorOut[]; };
layout(push_constant) uniform Push {
  uint width;
  uint height;
  uint iteration;
};

#define VKPT_DENOISE_PARAM
#define VKPT_DENOISE_ARG
#define VKPT_DENOISE_COLOR(i) colorIn[i]
#define VKPT_DENOISE_GUIDE(i) guide[i]
#define VKPT_DENOISE_ALBEDO(i) albedo[i].xyz
#include "shared/denoise.h"

void main() {
  uvec2 p = gl_GlobalInvocationID.xy;
  if (p.x >= width || p.y >= height) return;
  colorOut[p.y * width + p.x] = AtrousPixel(width, height, p.x, p.y, iteration);
}

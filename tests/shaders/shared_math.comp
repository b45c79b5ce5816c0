#version 460
// Test kernel: evaluates the shared RNG, sampling and intersection code on the GPU for
// invocation-derived inputs, so tests can compare every value with the C++ build of
// the same headers (bit-exact for integers, to a tolerance for floats).
#extension GL_GOOGLE_include_directive : require
#include "shared/layout.h"
#include "shared/rng.h"
#include "shared/sampling.h"
#include "shared/intersect.h"

layout(local_size_x = 64) in;

struct MathOut {
  uvec4 hash;  // Pcg4d(i, 3i + 1, 7, 11)
  vec4 rand;   // Random4(5, i, 2, 3)
  vec4 dir;    // xyz: cosine-sampled direction around a rand-derived normal; w: its pdf
  vec4 misc;   // xy: triangle barycentrics, z: slab entry t, w: triangle hit t
  vec4 sobol;  // xy: Sample2D(7, i, i >> 3, 2), zw: Sample2D(7, i >> 4, i, 5)
};
layout(std430, binding = 0) writeonly buffer Out { MathOut outputs[]; };

#include "shared_math_body.glsl"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(outputs.length())) return;
  outputs[i] = Evaluate(i);
}

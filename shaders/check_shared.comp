#version 460
// Compiles every shared header as GLSL, so a C++-only construct in shaders/shared/
// fails the build at once.
#extension GL_GOOGLE_include_directive : require
#include "shared/layout.h"
#include "shared/rng.h"
#include "shared/sampling.h"
#include "shared/intersect.h"
#include "shared/estimator.h"

layout(local_size_x = 64) in;

layout(std430, binding = kBindingTriangles) readonly buffer Triangles { Triangle triangles[]; };
layout(std430, binding = kBindingNodes) readonly buffer Nodes { BvhNode nodes[]; };
layout(std430, binding = kBindingAccum) buffer Out { vec4 results[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  vec4 r = Random4(1u, i, 2u, LightGroup(3u));
  Frame f = FrameFromNormal(normalize(vec3(r.x, r.y, r.z) - 0.5f));
  vec3 d = FrameToWorld(f, SampleCosineHemisphere(r.x, r.y));
  Triangle t = triangles[i];
  BvhNode n = nodes[i];
  float tb = IntersectBox(n.lo, n.hi, OffsetRayOrigin(vec3(0.0f), d), SafeInverse(d), 1e30f);
  vec3 h = IntersectTriangle(t.v0, t.e1, t.e2, vec3(0.0f), d, tb);
  vec2 b = SampleUniformTriangle(r.z, r.w);
  results[i] = vec4(h, b.x + b.y + CosineHemispherePdf(d.z) + Luminance(d) + MaxComponent(d));
}

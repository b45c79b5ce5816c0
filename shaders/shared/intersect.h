// Ray/box and ray/triangle tests, shared by the CPU and GPU renderers.
#ifndef VKPT_INTERSECT_H
#define VKPT_INTERSECT_H
#include "prelude.h"

VKPT_BEGIN_NAMESPACE

// 1/d per component, with zero components replaced by a tiny signed value first: the
// slab test then multiplies by a huge finite number instead of ∞, so a ray lying in a
// slab plane gives 0·(1e30) = 0 rather than 0·∞ = NaN.
VKPT_FN vec3 SafeInverse(vec3 d) {
  const float tiny = 1e-30f;
  vec3 s = vec3(abs(d.x) < tiny ? (d.x < 0.0f ? -tiny : tiny) : d.x,
                abs(d.y) < tiny ? (d.y < 0.0f ? -tiny : tiny) : d.y,
                abs(d.z) < tiny ? (d.z < 0.0f ? -tiny : tiny) : d.z);
  return vec3(1.0f) / s;
}

// Minimum and maximum as plain selects, for values that are never NaN. GLSL's min/max
// must return the non-NaN operand, which costs lavapipe a NaN test and a blend per call.
VKPT_FN float MinNotNaN(float a, float b) { return b < a ? b : a; }
VKPT_FN float MaxNotNaN(float a, float b) { return a < b ? b : a; }
VKPT_FN vec3 MinNotNaN(vec3 a, vec3 b) { return mix(a, b, lessThan(b, a)); }
VKPT_FN vec3 MaxNotNaN(vec3 a, vec3 b) { return mix(a, b, lessThan(a, b)); }

// Slab test (Kay & Kajiya 1986; GAMES101 Bounds3::IntersectP). Returns the entry
// distance, or -1 when the box is missed or lies beyond tMax. The exit distance is
// enlarged by 1 + 2γ₃ (pbrt-v3 §3.9.2) so rounding can never miss a box that the ray
// truly grazes. The slab distances are never NaN: the loader rejects non-finite
// positions, and SafeInverse keeps 1/d finite.
VKPT_FN float IntersectBox(vec3 lo, vec3 hi, vec3 origin, vec3 invDir, float tMax) {
  vec3 t0 = (lo - origin) * invDir;
  vec3 t1 = (hi - origin) * invDir;
  vec3 tNear = MinNotNaN(t0, t1);
  vec3 tFar = MaxNotNaN(t0, t1);
  float tEnter = MaxNotNaN(MaxNotNaN(tNear.x, tNear.y), MaxNotNaN(tNear.z, 0.0f));
  float tExit = MinNotNaN(MinNotNaN(tFar.x, tFar.y), MinNotNaN(tFar.z, tMax)) * 1.0000004f;
  return tEnter <= tExit ? tEnter : -1.0f;
}

// Möller–Trumbore ray/triangle test on (v0, e1 = v1 - v0, e2 = v2 - v0), two-sided.
// Returns (t, b1, b2) with t in (0, tMax), or t = -1 for a miss. Degenerate
// (zero-area) triangles have det = 0 and are never hit.
VKPT_FN vec3 IntersectTriangle(vec3 v0, vec3 e1, vec3 e2, vec3 origin, vec3 dir, float tMax) {
  vec3 p = cross(dir, e2);
  float det = dot(e1, p);
  if (det == 0.0f) return vec3(-1.0f, 0.0f, 0.0f);
  float invDet = 1.0f / det;
  vec3 s = origin - v0;
  float b1 = dot(s, p) * invDet;
  if (b1 < 0.0f || b1 > 1.0f) return vec3(-1.0f, 0.0f, 0.0f);
  vec3 q = cross(s, e1);
  float b2 = dot(dir, q) * invDet;
  if (b2 < 0.0f || b1 + b2 > 1.0f) return vec3(-1.0f, 0.0f, 0.0f);
  float t = dot(e2, q) * invDet;
  if (!(t > 0.0f && t < tMax)) return vec3(-1.0f, 0.0f, 0.0f);
  return vec3(t, b1, b2);
}

// Moves a ray origin off surface point p along the geometric normal n by a few ULPs of
// p's coordinates (Wächter & Binder 2019, "A Fast and Robust Method for Avoiding
// Self-Intersection", Ray Tracing Gems ch. 6). The offset scales with |p|, so it works
// for a scene in millimetres as well as in kilometres; near the origin, where ULPs
// vanish, a small fixed offset takes over.
VKPT_FN float OffsetComponent(float p, float n) {
  const float originRegion = 1.0f / 32.0f;
  const float floatScale = 1.0f / 65536.0f;
  const float intScale = 256.0f;
  int ulps = int(intScale * n);
  float moved = intBitsToFloat(floatBitsToInt(p) + (p < 0.0f ? -ulps : ulps));
  return abs(p) < originRegion ? p + floatScale * n : moved;
}

// n must point to the side the new ray leaves from.
VKPT_FN vec3 OffsetRayOrigin(vec3 p, vec3 n) {
  return vec3(OffsetComponent(p.x, n.x), OffsetComponent(p.y, n.y), OffsetComponent(p.z, n.z));
}

VKPT_END_NAMESPACE

#endif

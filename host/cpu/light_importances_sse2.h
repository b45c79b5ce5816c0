// The light tree's four importances of a step (shared/light_importance.h) in SSE2 lanes,
// for the CPU's estimator (cpu_trace.h includes this first): the same operations in the
// same order as LightNodeImportance, each correctly rounded, so the same results (up to the
// sign of a zero), at a quarter of the instructions and without its branches.
// LightTree.FourNodeImportancesAreEachNodes holds them equal.
#pragma once

#include "render/render_scene.h"
#include "render/scene_access.h"
#include "shared/light_importance.h"

#ifdef __SSE2__
#include <emmintrin.h>

namespace vkpt::internal {
namespace sse2 {

inline __m128 Select(__m128 mask, __m128 a, __m128 b) { return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b)); }
inline __m128 CosSubClamped4(__m128 sinA, __m128 cosA, __m128 sinB, __m128 cosB) {
  __m128 sub = _mm_add_ps(_mm_mul_ps(cosA, cosB), _mm_mul_ps(sinA, sinB));
  return Select(_mm_cmpgt_ps(cosA, cosB), _mm_set1_ps(1.0f), sub);
}
inline __m128 SinSubClamped4(__m128 sinA, __m128 cosA, __m128 sinB, __m128 cosB) {
  __m128 sub = _mm_sub_ps(_mm_mul_ps(sinA, cosB), _mm_mul_ps(cosA, sinB));
  return _mm_andnot_ps(_mm_cmpgt_ps(cosA, cosB), sub);
}
// sqrt(max(0, 1 − c²)): glm's max(0, x) is x where 0 < x, else 0, as _mm_max_ps(x, 0).
inline __m128 SinOfCos4(__m128 c) {
  return _mm_sqrt_ps(_mm_max_ps(_mm_sub_ps(_mm_set1_ps(1.0f), _mm_mul_ps(c, c)), _mm_setzero_ps()));
}
inline __m128 Abs4(__m128 x) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), x); }

}  // namespace sse2

inline shader::LightImportances LightNodeImportancesSse2(const RenderScene& scene, glm::uvec4 nodes, glm::vec3 p,
                                                         glm::vec3 n) {
  using namespace sse2;
  // The nodes' three rows (center, radius; axis, intensity; cones, split) transposed.
  uint32_t first = nodes.x;
  __m128 rows[3][4];
  for (int lane = 0; lane < 4; ++lane) {
    const float* node = &VKPT_LIGHT_NODE(nodes[lane] == shader::kInvalidIndex ? first : nodes[lane]).center.x;
    for (int row = 0; row < 3; ++row) rows[row][lane] = _mm_loadu_ps(node + 4 * row);
  }
  for (auto& row : rows) _MM_TRANSPOSE4_PS(row[0], row[1], row[2], row[3]);
  const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f);
  const __m128 radius = rows[0][3], intensity = rows[1][3];
  const __m128 cosO = rows[2][0], sinO = rows[2][1], cosE = rows[2][2];
  const __m128 twoSided = _mm_castsi128_ps(_mm_srai_epi32(_mm_castps_si128(rows[2][3]), 31));
  __m128 dx = _mm_sub_ps(_mm_set1_ps(p.x), rows[0][0]);
  __m128 dy = _mm_sub_ps(_mm_set1_ps(p.y), rows[0][1]);
  __m128 dz = _mm_sub_ps(_mm_set1_ps(p.z), rows[0][2]);
  __m128 d2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
  __m128 r2 = _mm_mul_ps(radius, radius);
  __m128 away = _mm_cmpgt_ps(d2, zero);
  __m128 invDist = _mm_and_ps(away, _mm_div_ps(one, _mm_sqrt_ps(d2)));
  __m128 wx = _mm_and_ps(away, _mm_mul_ps(dx, invDist));
  __m128 wy = _mm_and_ps(away, _mm_mul_ps(dy, invDist));
  __m128 wz = Select(away, _mm_mul_ps(dz, invDist), one);
  __m128 outside = _mm_cmpgt_ps(d2, r2);
  __m128 sinB = _mm_and_ps(outside, _mm_mul_ps(radius, invDist));
  __m128 cosB = Select(outside, SinOfCos4(sinB), _mm_set1_ps(-1.0f));
  __m128 cosW =
      _mm_add_ps(_mm_add_ps(_mm_mul_ps(rows[1][0], wx), _mm_mul_ps(rows[1][1], wy)), _mm_mul_ps(rows[1][2], wz));
  cosW = Select(twoSided, Abs4(cosW), cosW);
  __m128 sinW = SinOfCos4(cosW);
  __m128 cosX = CosSubClamped4(sinW, cosW, sinO, cosO);
  __m128 sinX = SinSubClamped4(sinW, cosW, sinO, cosO);
  __m128 cosP = CosSubClamped4(sinX, cosX, sinB, cosB);
  __m128 near2 = _mm_max_ps(_mm_set1_ps(1e-12f), d2);
  __m128 importance = _mm_div_ps(_mm_mul_ps(intensity, cosP), _mm_max_ps(r2, near2));
  __m128 estimate =
      _mm_div_ps(_mm_mul_ps(intensity, _mm_max_ps(zero, cosX)), _mm_max_ps(_mm_mul_ps(_mm_set1_ps(0.01f), r2), near2));
  if (n != glm::vec3(0.0f)) {
    __m128 cosI = Abs4(_mm_add_ps(_mm_add_ps(_mm_mul_ps(wx, _mm_set1_ps(n.x)), _mm_mul_ps(wy, _mm_set1_ps(n.y))),
                                  _mm_mul_ps(wz, _mm_set1_ps(n.z))));
    importance = _mm_mul_ps(importance, CosSubClamped4(SinOfCos4(cosI), cosI, sinB, cosB));
    estimate = _mm_mul_ps(estimate, cosI);
  }
  __m128 valid = _mm_castsi128_ps(
      _mm_cmpeq_epi32(_mm_setr_epi32(nodes.x == shader::kInvalidIndex, nodes.y == shader::kInvalidIndex,
                                     nodes.z == shader::kInvalidIndex, nodes.w == shader::kInvalidIndex),
                      _mm_setzero_si128()));
  __m128 keep = _mm_and_ps(valid, _mm_and_ps(_mm_cmpgt_ps(cosP, cosE), _mm_cmpgt_ps(importance, zero)));
  shader::LightImportances r;
  _mm_storeu_ps(&r.bound.x, _mm_and_ps(keep, importance));
  _mm_storeu_ps(&r.estimate.x, _mm_and_ps(keep, estimate));
  return r;
}

}  // namespace vkpt::internal

#define VKPT_LIGHT_IMPORTANCES(nodes, p, n) ::vkpt::internal::LightNodeImportancesSse2(scene, nodes, p, n)
#endif

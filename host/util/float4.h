// Four floats in one SSE/NEON register through the compiler's generic vector extension
// (GCC and Clang): portable; only min/max name SSE instructions, with a generic fallback. Used where a loop handles x,
// y, z (and a spare lane) at once: the CPU traversal's box and triangle tests and the BVH builder's binning.
#pragma once

#include <cstdint>
#include <cstring>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace vkpt::internal {

typedef float Float4 __attribute__((vector_size(16)));
typedef int32_t Int4 __attribute__((vector_size(16)));

inline Float4 Splat4(float x) { return Float4{x, x, x, x}; }
// Four floats from memory that need not be 16-byte aligned (a vec3 and what follows it).
inline Float4 Load4(const float* p) {
  Float4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
// Per lane a < b ? a : b and a > b ? a : b. That is exactly what SSE's minps/maxps do
// (NaN and signed zeros included), but GCC 12 compiles the selects to compare-and-blend,
// so on x86 the instructions are named.
#if defined(__SSE__)
inline Float4 Min4(Float4 a, Float4 b) { return Float4(_mm_min_ps(__m128(a), __m128(b))); }
inline Float4 Max4(Float4 a, Float4 b) { return Float4(_mm_max_ps(__m128(a), __m128(b))); }
#else
inline Float4 Min4(Float4 a, Float4 b) { return a < b ? a : b; }
inline Float4 Max4(Float4 a, Float4 b) { return a > b ? a : b; }
#endif
// One bit per lane of a comparison's result (lane k -> bit k).
inline int Mask4(Int4 m) {
#if defined(__SSE__)
  return _mm_movemask_ps(__m128(m));
#else
  return (m[0] & 1) | (m[1] & 2) | (m[2] & 4) | (m[3] & 8);
#endif
}
inline Float4 SwapHalves4(Float4 v) {
#if defined(__clang__)
  return __builtin_shufflevector(v, v, 2, 3, 0, 1);
#else
  return __builtin_shuffle(v, Int4{2, 3, 0, 1});
#endif
}

}  // namespace vkpt::internal

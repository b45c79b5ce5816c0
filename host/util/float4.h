// Four floats in one SSE/NEON register through the compiler's generic vector extension
// (GCC and Clang): portable, no intrinsics. Used where a loop handles x, y, z (and a
// spare lane) at once: the CPU traversal's child-pair test and the BVH builder's binning.
#pragma once

#include <cstdint>
#include <cstring>

namespace vkpt {

typedef float Float4 __attribute__((vector_size(16)));
typedef int32_t Int4 __attribute__((vector_size(16)));

inline Float4 Splat4(float x) { return Float4{x, x, x, x}; }
// Four floats from memory that need not be 16-byte aligned (a vec3 and what follows it).
inline Float4 Load4(const float* p) {
  Float4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
// x86 minps/maxps are exactly these selects, and the compilers emit them for it.
inline Float4 Min4(Float4 a, Float4 b) { return a < b ? a : b; }
inline Float4 Max4(Float4 a, Float4 b) { return a > b ? a : b; }
inline Float4 SwapHalves4(Float4 v) {
#if defined(__clang__)
  return __builtin_shufflevector(v, v, 2, 3, 0, 1);
#else
  return __builtin_shuffle(v, Int4{2, 3, 0, 1});
#endif
}

}  // namespace vkpt

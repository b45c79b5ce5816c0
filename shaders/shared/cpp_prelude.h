// C++ side of the GLSL/C++ shared headers. Included only when __cplusplus is defined.
//
// The headers in shaders/shared/ are written in the common subset of GLSL 4.60 and
// C++20 so that the CPU reference tracer and the compute shader run the *same* RNG,
// sampling and intersection code. GLM mirrors GLSL's types and built-ins (vec3, dot,
// floatBitsToInt, ...), so on the C++ side all that is needed is to bring them into scope.
#pragma once

#include <cstdint>
#include <cmath>
#include <glm/glm.hpp>

namespace vkpt::shader {
using namespace glm;
using uint = std::uint32_t;
}  // namespace vkpt::shader

// Free functions in shared headers are `VKPT_FN`: inline in C++, plain in GLSL.
#define VKPT_FN inline
// A function only some materials reach (a film, an anisotropic lobe): out of line in C++,
// so that the functions of the common path that call it stay small enough to inline (a
// specialization constant drops it from a shader that does not need it).
#define VKPT_RARE_FN [[gnu::noinline]] inline
// A parameter the function reads and writes: a reference in C++, `inout` in GLSL.
#define VKPT_INOUT(T) T&
// A value whose computation no compiler may fuse into FMAs: GLSL's `precise`. C++ builds
// use -ffp-contract=off (CMakeLists.txt) everywhere instead.
#define VKPT_PRECISE
#define VKPT_BEGIN_NAMESPACE namespace vkpt::shader {
#define VKPT_END_NAMESPACE }

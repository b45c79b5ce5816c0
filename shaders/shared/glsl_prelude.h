// GLSL side of the shared headers: the macros cpp_prelude.h defines for C++.
#ifndef VKPT_GLSL_PRELUDE_H
#define VKPT_GLSL_PRELUDE_H
#define VKPT_FN
#define VKPT_RARE_FN
#define VKPT_INOUT(T) inout T
#define VKPT_PRECISE precise
#define VKPT_BEGIN_NAMESPACE
#define VKPT_END_NAMESPACE
#endif

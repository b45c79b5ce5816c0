// Include first from every shared header: picks the language-specific prelude.
#ifndef VKPT_PRELUDE_H
#define VKPT_PRELUDE_H
#ifdef __cplusplus
#include "cpp_prelude.h"
#else
#include "glsl_prelude.h"
#endif
#endif

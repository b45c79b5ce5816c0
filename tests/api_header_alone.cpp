// The public header compiles on its own, before any other, with nothing but the standard
// library: what a program that installs vkpt sees.
#include "vkpt/vkpt.h"

static_assert(sizeof(vkpt::RenderOptions) > 0 && sizeof(vkpt::SceneOptions) > 0);

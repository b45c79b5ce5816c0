// The shared estimator (shaders/shared/path.h) instantiated for the CPU: its scene access
// and traversal (cpu/cpu_trace.h), the environment and the general estimator.
#pragma once

#include "cpu/cpu_trace.h"
#include "shared/environment.h"
#include "shared/path.h"

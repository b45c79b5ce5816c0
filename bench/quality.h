// vkpt-bench --quality: the seconds each backend needs to reach a relMSE against a
// converged reference, for each light sampler the scene can use.
#pragma once

#include "bench_options.h"

namespace vkpt::internal::bench {

// Prints the figures (text, or JSON with --json); returns the exit status.
int Quality(const Options& o, unsigned threads);

}  // namespace vkpt::internal::bench

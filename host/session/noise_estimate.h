// How noisy a render still is, from its own sums: the estimate behind --noise-target and
// adaptive sampling. vkpt-bench measures an image against a converged reference r as
// relMSE = mean over pixels and channels of (a − r)² / (r² + 0.01); the expectation of
// (a − r)² is the variance of the pixel's mean, which the sums estimate, and r is
// replaced by a. The 0.01 keeps black pixels from dividing by zero (as the bench does).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "render/film.h"

namespace vkpt::internal {

// One pixel's estimated relative squared error, averaged over its channels; infinite
// with fewer than two samples (no variance estimate yet).
double PixelRelativeError(const PixelSums& s);

// The image's estimated relMSE: the mean of PixelRelativeError over its pixels.
double EstimatedRelMse(const FrameSums& sums);

// Adaptive sampling's decision after a pass (in the spirit of Cycles' noise threshold):
// pixel i stays active while it or one of its eight neighbours has an estimated error
// above `target` — the neighbours guard against a pixel whose few samples all missed a
// rare light path and so look converged. A pixel once inactive stays inactive (its sums
// no longer change, nor do the decisions of its neighbourhood's converged pixels). The
// decision reads the sums alone, so equal sums give equal decisions on any backend.
// Returns the number of active pixels.
uint64_t UpdateActivePixels(const FrameSums& sums, double target, std::vector<uint8_t>& active);

}  // namespace vkpt::internal

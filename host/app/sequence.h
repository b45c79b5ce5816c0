// --frames FIRST:LAST[:STEP]: the frames of a sequence, each a render of its own options —
// posed k / --fps seconds into the --animation, turned by k × --orbit, written to a path
// numbered k — so that any frame rendered alone with those options is the same image.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "app/options.h"

namespace vkpt::internal {

// FIRST, FIRST + STEP, … up to LAST.
std::vector<uint32_t> FrameNumbers(const FrameRange& range);

// `out` for frame `frame`: its last run of '#' replaced by the number, zero-padded to the
// run's length ("turn.###.png" → "turn.007.png"); without one, ".NNNN" before the
// extension ("turn.png" → "turn.0007.png").
std::string FramePath(const std::string& out, uint32_t frame);

// The options of frame `frame` of `o`'s sequence: --at k / --fps (with an --animation),
// --orbit k × --orbit, --out its FramePath; no --stats of its own.
Options FrameOptions(const Options& o, uint32_t frame);

// --stats of a sequence: {"frames": [each frame's stats object, in order]}, written
// atomically.
void WriteSequenceStats(const std::string& path, const std::vector<std::string>& frames);

}  // namespace vkpt::internal

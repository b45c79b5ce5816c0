// --frames FIRST:LAST[:STEP]: the frames of a sequence, each a render of its own options —
// posed k / --fps seconds into the --animation, turned by k × --orbit, written to a path
// numbered k — so that any frame rendered alone with those options is the same image.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "app/options.h"

namespace vkpt::internal {

// FIRST, FIRST + STEP, … up to LAST: how many, and the i-th (from 0), computed rather
// than listed, so that a million-frame range costs nothing before its first frame.
uint64_t FrameCount(const FrameRange& range);
uint32_t FrameNumber(const FrameRange& range, uint64_t i);

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

// Where a render session's samples come from: passes on this process's own backend
// (session/local_passes.h), or chunks dealt among the ranks of an MPI job
// (session/dealt_chunks.h). The session's loop (session/render_session.h) owns the
// budgets, decisions, checkpoints and reports; a source only adds samples to the frame,
// each pixel's in sample order, so the sums it returns depend on the samples taken alone.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cluster/rank_share.h"
#include "render/film.h"

namespace vkpt::internal {

// What the session asks of a source for its next step.
struct SampleRequest {
  uint32_t done = 0;                // samples per pixel in the frame so far
  uint32_t limit = 0;               // no sample at or past this count (the spp bound or a decision point)
  std::span<const uint8_t> active;  // the pixels that take samples (empty: every pixel)
  // --time: no new work begins after this moment.
  std::optional<std::chrono::steady_clock::time_point> deadline;
  // The frame's samples per pixel so far, fractional within a step, now and then.
  std::function<void(double spp)> progress;
  // Whether to stop (a signal, a caller's cancel): asked between passes, so every sample
  // begun is added. Empty: never.
  std::function<bool()> stop;
};

class SampleSource {
 public:
  virtual ~SampleSource() = default;
  // Adds the next samples [done, done + n) with done + n ≤ limit and returns n; 0 when
  // no more will come (the limit is reached, the deadline has passed, or `stop` said so
  // and every sample begun has been added).
  virtual uint32_t Advance(const SampleRequest& request) = 0;
  virtual FrameSums Sums() = 0;  // the frame's sums so far
  // The AOV pass of every pixel (render/film.h's AovRequest), on this process.
  virtual AovSums RenderAovs(const AovRequest& request) = 0;
  // After the last Advance: what each rank of an MPI job did (empty for one process).
  virtual std::vector<RankShare> Finish() { return {}; }
  virtual std::string Engine() const = 0;  // for reports: "cpu (2 threads)", "mpi: 2 ranks, rank 0 …"
};

}  // namespace vkpt::internal

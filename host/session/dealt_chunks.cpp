#include "session/dealt_chunks.h"

#include <algorithm>
#include <chrono>

#include "session/chunked_frame.h"

namespace vkpt::internal {

DealtChunks::DealtChunks(Cluster& cluster, FrameRenderer& frame, const ChunkPlan& plan)
    : cluster_(cluster),
      frame_(frame),
      plan_(plan),
      render_(ChunkRendererOf(frame, plan)),
      dealer_(cluster, plan, render_) {}

uint32_t DealtChunks::Advance(const SampleRequest& request) {
  if (request.done >= request.limit) return 0;
  const uint32_t limit = (request.limit + plan_.chunkSpp - 1) / plan_.chunkSpp;  // chunks before it
  dealer_.Open(limit, std::vector<uint8_t>(request.active.begin(), request.active.end()));
  // A stop or the deadline ends the dealing; the chunks dealt still come back.
  const auto stopDealing = [&request] {
    return (request.stop && request.stop()) ||
           (request.deadline && std::chrono::steady_clock::now() >= *request.deadline);
  };
  const uint32_t chunk = request.done / plan_.chunkSpp;
  std::optional<FrameSums> sums = dealer_.Next(stopDealing);
  if (!sums) return 0;
  AddChunk(sums_, *sums);
  return plan_.Samples(chunk);
}

std::string DealtChunks::Engine() const {
  return "mpi: " + std::to_string(cluster_.Size()) + " ranks, rank 0 " + frame_.Engine();
}

}  // namespace vkpt::internal

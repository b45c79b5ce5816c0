// The samples of a frame on rank 0 of an MPI job: whole chunks dealt among the ranks
// (cluster/chunk_dealer.h), added to the frame's sums in chunk order as they come back,
// so the sums are those a single process makes, bit for bit. A step is one chunk; the
// dealer opens the chunks before each decision point only once the session asks for them,
// that is after it has judged the frame at the point before.
#pragma once

#include <cstdint>
#include <vector>

#include "cluster/chunk_dealer.h"
#include "cluster/cluster.h"
#include "session/sample_source.h"

namespace vkpt::internal {

class DealtChunks final : public SampleSource {
 public:
  // `frame` is rank 0's own backend's; it renders rank 0's chunks and the AOV pass.
  DealtChunks(Cluster& cluster, FrameRenderer& frame, const ChunkPlan& plan);

  uint32_t Advance(const SampleRequest& request) override;
  FrameSums Sums() override { return sums_; }
  AovSums RenderAovs(const AovRequest& request) override { return frame_.RenderAovs(request); }
  std::vector<RankShare> Finish() override { return dealer_.Finish(); }
  std::string Engine() const override;

 private:
  Cluster& cluster_;
  FrameRenderer& frame_;
  const ChunkPlan plan_;
  const ChunkRenderer render_;
  ChunkDealer dealer_;
  FrameSums sums_;  // the chunks taken, in order
};

}  // namespace vkpt::internal

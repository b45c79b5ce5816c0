// The transport of one frame's chunks (session/chunked_frame.h) among the ranks of a
// Cluster. Rank 0 deals chunk indices on request and renders chunks itself on a thread of
// its own; the session adds the chunks' sums to the frame's in chunk order, so the image
// is the one a single process makes, bit for bit, whatever the ranks, their speeds and the
// order in which chunks come back. A rank that is done with a chunk asks for the next:
// fast ranks take more chunks (dynamic balancing).
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cluster/chunk_message.h"
#include "cluster/cluster.h"
#include "cluster/rank_share.h"
#include "render/film.h"

namespace vkpt::internal {

struct ChunkPlan {
  uint32_t spp = 0;       // samples per pixel of the frame
  uint32_t chunkSpp = 0;  // of each chunk but perhaps the last
  uint32_t Chunks() const { return (spp + chunkSpp - 1) / chunkSpp; }
  uint32_t Begin(uint32_t chunk) const { return chunk * chunkSpp; }
  uint32_t Samples(uint32_t chunk) const { return std::min(chunkSpp, spp - Begin(chunk)); }
};

// Renders chunk `chunk` of the plan on this rank: its sums alone, with samples in the
// pixels `active` marks (empty: every pixel).
using ChunkRenderer = std::function<FrameSums(uint32_t chunk, std::span<const uint8_t> active)>;

// A chunk on `frame` alone: cleared, then the chunk's samples. For the tests of an MPI
// job (docs/testing.md), VKPT_TEST_CHUNK_DELAY_MS slows the rank down by that much per
// chunk, and VKPT_TEST_FAIL_AFTER_CHUNKS=N makes it fail after N chunks of its own.
ChunkRenderer ChunkRendererOf(FrameRenderer& frame, const ChunkPlan& plan);

// Rank 0's side of a frame dealt among the ranks. The session (session/dealt_chunks.h)
// opens the chunks before each decision point as it reaches it, and takes the chunks'
// sums back one by one in chunk order; meanwhile the dealer answers every rank's requests
// and renders chunks itself on a thread that never calls MPI. No chunk past the open limit
// is dealt, so a decision judges every chunk dealt before it and no work is thrown away.
class ChunkDealer {
 public:
  ChunkDealer(Cluster& cluster, const ChunkPlan& plan, const ChunkRenderer& render);
  ~ChunkDealer();

  // From now on chunks before `limit` may be dealt, sampling the pixels `active` marks
  // (empty: every pixel).
  void Open(uint32_t limit, const std::vector<uint8_t>& active);
  // The next chunk's sums, in chunk order, once it is back; nothing when no further chunk
  // will come: the plan's chunks are all taken, or `stopDealing` (asked while waiting)
  // said to deal no more and every chunk dealt has been taken.
  std::optional<FrameSums> Next(const std::function<bool()>& stopDealing);
  // After the last Next: tells every rank there are no more chunks, and what each did.
  std::vector<RankShare> Finish();

 private:
  bool Serve();  // one round of messages and rank 0's own chunks; whether anything happened
  bool Assign(int rank);

  class LocalRenderer;
  Cluster& cluster_;
  const ChunkPlan plan_;
  std::unique_ptr<LocalRenderer> local_;
  std::map<uint32_t, FrameSums> pending_;  // back, not yet taken
  uint32_t next_ = 0;                      // the chunk Next hands back
  int told_ = 0;                           // ranks told there are no more chunks
  std::vector<int> waiting_;               // ranks whose request waits for Open
  std::shared_ptr<const std::vector<uint8_t>> active_;
  std::vector<std::shared_ptr<const std::vector<uint8_t>>> sent_;  // the active pixels each rank has
  std::vector<RankShare> ranks_;
};

// Every other rank: renders the chunks rank 0 deals it until rank 0 says there are none.
void RenderDealtChunks(Cluster& cluster, const ChunkRenderer& render);

}  // namespace vkpt::internal

// One frame's chunks (image/chunked_frame.h) shared among the ranks of a Cluster. Rank 0
// deals chunk indices on request, renders chunks itself on a thread of its own, and adds
// every chunk's sums to the frame's in chunk order as they arrive, so the image is the one
// a single process makes, bit for bit, whatever the ranks, their speeds and the order in
// which chunks come back. A rank that is done with a chunk asks for the next: fast ranks
// take more chunks (dynamic balancing).
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "dist/cluster.h"
#include "image/film.h"

namespace vkpt {

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

// What one rank did.
struct RankShare {
  std::string name;          // "rank 1 (host)"
  uint32_t chunks = 0;       // chunks it rendered
  uint64_t bytesSent = 0;    // its chunks' sums as sent to rank 0 (0 for rank 0)
  double renderSeconds = 0;  // rendering its chunks, by its own clock
};

struct DealtFrame {
  FrameSums sums;              // chunks [0, chunks) added in order
  uint32_t chunks = 0;         // a prefix of the plan: fewer if dealing stopped early
  uint32_t spp = 0;            // samples per pixel of those chunks
  bool decidedToStop = false;  // Decisions::decide ended the frame
  std::vector<RankShare> ranks;
};

// Adaptive sampling and noise targets across ranks. At each decision point (a sample count
// that ends a chunk: app/render_loop.h) rank 0 judges the chunks added so far, and may end
// the frame there or change which pixels the later chunks sample. No chunk past a
// decision point is dealt before that judgement, so every chunk is rendered with the
// pixels a single process would sample, and no work is thrown away.
struct Decisions {
  std::function<uint32_t(uint32_t spp)> nextPoint;  // the first decision point after spp
  // Judges the frame at `spp` samples per pixel: updates `active` (empty: every pixel) and
  // returns whether the frame ends there.
  std::function<bool(const FrameSums& sums, uint32_t spp, std::vector<uint8_t>& active)> decide;
};

struct DealerHooks {
  Decisions decisions;                                             // none without nextPoint
  std::function<bool()> stopDealing;                               // no more chunks (time, signal)
  std::function<void(double)> progress;                            // chunks added / planned
  std::function<void(const FrameSums&, uint32_t spp)> checkpoint;  // the chunks added so far
  double checkpointSeconds = 0.0;
};

// Rank 0. A failure on any rank, its own included, prints that rank's message and ends
// the job (Cluster::Abort) before anything is written.
DealtFrame DealChunks(Cluster& cluster, const ChunkPlan& plan, const ChunkRenderer& render,
                      const DealerHooks& hooks = {});

// Every other rank: renders the chunks rank 0 deals it until rank 0 says there are none.
void RenderDealtChunks(Cluster& cluster, const ChunkRenderer& render);

// A chunk's sums as sent, with the seconds it took to render, and back: a 48-byte header
// and 28 bytes per pixel when every sum is a float exactly (a GPU's chunk), else 52.
std::vector<uint8_t> EncodeChunk(uint32_t chunk, const FrameSums& sums, double seconds);
FrameSums DecodeChunk(const std::vector<uint8_t>& bytes, uint32_t* chunk, double* seconds);

}  // namespace vkpt

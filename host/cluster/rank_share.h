// What one rank of an MPI job did for a frame: the session reports it (render_session.h)
// without knowing how chunks are dealt (chunk_dealer.h).
#pragma once

#include <cstdint>
#include <string>

namespace vkpt::internal {

struct RankShare {
  std::string name;          // "rank 1 (host)"
  uint32_t chunks = 0;       // chunks it rendered
  uint64_t bytesSent = 0;    // its chunks' sums as sent to rank 0 (0 for rank 0)
  double renderSeconds = 0;  // rendering its chunks, by its own clock
};

}  // namespace vkpt::internal

#include "cluster/cluster.h"

#include <chrono>
#include <cstdlib>
#include <thread>

namespace vkpt::internal {

std::string Cluster::Name(int rank) const {
  const std::string host = rank == Rank() ? Host() : size_t(rank) < hosts_.size() ? hosts_[rank] : "?";
  return "rank " + std::to_string(rank) + " (" + host + ")";
}

void Cluster::Abort(int status) {
  AbortJob(status);
  std::_Exit(status);
}

Cluster::Envelope Cluster::Wait(int from, int tag) {
  // 0.2 ms between polls: a rank waiting for its next chunk costs nothing measurable, and
  // an answer comes far sooner than a chunk renders.
  for (;;) {
    if (std::optional<Envelope> e = Poll(from, tag)) return *e;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
}

}  // namespace vkpt::internal

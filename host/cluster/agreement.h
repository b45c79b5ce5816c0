// Steps every rank of an MPI job takes (parsing the options, loading the scene): their
// outcomes gathered, so that a failure anywhere ends the job on every rank, and rank 0
// alone says why, once.
#pragma once

#include <cstdint>
#include <string>

#include "cluster/cluster.h"

namespace vkpt::internal {

// Every rank's `status` (0: success) and `message` gathered at rank 0. When some failed,
// rank 0 prints each different message once as "vkpt: <kind>: …" (naming the ranks when
// the messages differ between ranks), and every rank returns the worst status.
int AgreeOnOutcome(Cluster& cluster, int status, const std::string& message, const char* kind);

}  // namespace vkpt::internal

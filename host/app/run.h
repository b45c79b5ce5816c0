// The runs of `vkpt` after its options are parsed: one process (Run), or one rank of an
// MPI job (RunRank), each going through the same loop over frames (a single image is a
// sequence of one): preparing the scene, rendering a session and writing its files and
// reports; and the tools that render nothing (--list-devices, --diff).
#pragma once

#include "app/options.h"
#include "cluster/cluster.h"

namespace vkpt::internal {

// Returns the exit status; throws Error for a failure.
int Run(const Options& o);

// One rank of an MPI job: every rank parses the options, loads the scene and builds its
// arrays; rank 0 deals the chunks and writes the files, the others render what it deals
// them. Returns the exit status, the same on every rank.
int RunRank(Cluster& cluster, int argc, char** argv);

}  // namespace vkpt::internal

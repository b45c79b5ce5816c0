// vkpt built without MPI: one process, and a clear error if a launcher started several.
#include <cstdlib>

#include "cluster/cluster.h"
#include "cluster/launcher_env.h"
#include "util/error.h"

namespace vkpt::internal {

std::unique_ptr<Cluster> JoinCluster(int*, char***) {
  const int size = LauncherProcessCount();
  if (size > 1)
    throw Error("an MPI launcher started " + std::to_string(size) +
                " processes, but this vkpt was built without MPI (install libopenmpi-dev and "
                "configure again); each would render the whole frame");
  return nullptr;
}

std::string ClusterSupport() { return "none (built without MPI)"; }

}  // namespace vkpt::internal

#include "cluster/launcher_env.h"

#include <cstdlib>
#include <initializer_list>

namespace vkpt::internal {

int LauncherProcessCount() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    if (const char* v = std::getenv(name)) {
      const long n = std::strtol(v, nullptr, 10);
      if (n > 0) return int(n);
    }
  }
  return 1;
}

}  // namespace vkpt::internal

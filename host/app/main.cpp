// vkpt: the command line. Parse the options, then run: one process (app/run.h opens the
// scene and renders it through the library, app/scene_client.h, then writes and reports),
// or one rank of an MPI job. Data flows one way:
//   glTF file → Scene (host/scene) → BVH + RenderScene (host/bvh, host/render)
//   → renderer (host/cpu or host/vk) → session (host/session) → Image (host/image) → file.
#include <signal.h>

#include <cstdio>
#include <exception>
#include <memory>
#include <new>

#include "app/options.h"
#include "app/run.h"
#include "cluster/cluster.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

// An MPI job's rank: every failure ends the whole job.
int MainOfRank(Cluster& cluster, int argc, char** argv) {
  try {
    return RunRank(cluster, argc, argv);
  } catch (const std::exception& e) {
    PrintError("error", cluster.Name(cluster.Rank()) + ": " + e.what());
    cluster.Abort(1);
  }
  return 1;
}

int MainOfProcess(int argc, char** argv) {
  Options o;
  try {
    o = ParseOptions(argc, argv);
  } catch (const UsageError& e) {
    PrintError("usage error", e.what());
    return 2;
  }
  if (o.help) {
    std::fputs(HelpText().c_str(), stdout);
    return 0;
  }
  if (o.version) {
    std::printf("vkpt %s\ndistributed rendering: %s\n", VKPT_VERSION, ClusterSupport().c_str());
    return 0;
  }
  try {
    return Run(o);
  } catch (const UsageError& e) {
    PrintError("usage error", e.what());
    return 2;
  } catch (const Error& e) {
    PrintError("error", e.what());
  } catch (const std::bad_alloc&) {
    PrintError("error", o.scene + ": out of memory");
  } catch (const std::exception& e) {
    PrintError("error", o.scene + ": " + e.what());
  }
  return 1;
}

}  // namespace
}  // namespace vkpt::internal

int main(int argc, char** argv) {
  using namespace vkpt::internal;
  // Past a file-size limit (ulimit -f) the kernel sends SIGXFSZ, whose default action
  // kills vkpt mid-write with the temporary left behind; ignored, write(2) fails with
  // EFBIG and the checked writer reports it and cleans up.
  signal(SIGXFSZ, SIG_IGN);
  std::unique_ptr<Cluster> cluster;
  try {
    cluster = JoinCluster(&argc, &argv);
  } catch (const Error& e) {
    PrintError("error", e.what());
    return 1;
  }
  return cluster ? MainOfRank(*cluster, argc, argv) : MainOfProcess(argc, argv);
}

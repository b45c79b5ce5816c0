// The processes of one job, when an MPI launcher (mpirun, srun) started several: who this
// one is, and the few messages vkpt's chunk dealing needs (cluster/chunk_dealer.h). Built
// over MPI when CMake found it (cluster_mpi.cpp), else over nothing (cluster_single.cpp),
// so that no other file knows whether MPI is there.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace vkpt::internal {

class Cluster {
 public:
  virtual ~Cluster() = default;  // leaves the job (MPI_Finalize)
  virtual int Rank() const = 0;
  virtual int Size() const = 0;
  virtual const std::string& Host() const = 0;
  // "rank 2 (host)": rank 0 knows every rank's host (gathered at the start), the others
  // their own.
  std::string Name(int rank) const;

  // Point to point, in order between two ranks for the same tag; any size (sent in parts).
  virtual void Send(int to, int tag, std::span<const uint8_t> bytes) = 0;
  struct Envelope {
    int from, tag;
  };
  // A message waiting for this rank, from `from` (or anyone: -1) with `tag` (or any: -1).
  virtual std::optional<Envelope> Poll(int from = -1, int tag = -1) = 0;
  virtual std::vector<uint8_t> Receive(int from, int tag) = 0;
  // Blocks (sleeping, not spinning: ranks may share cores) until Poll finds a message.
  Envelope Wait(int from = -1, int tag = -1);

  // Collectives, which every rank must call in the same order.
  virtual std::vector<std::string> Gather(const std::string& mine) = 0;  // at rank 0; empty elsewhere
  virtual bool AllEqual(uint64_t mine) = 0;                              // every rank's value the same
  virtual int MaxOf(int mine) = 0;                                       // on every rank

  // Ends every process of the job with `status` (MPI_Abort), from any rank.
  [[noreturn]] void Abort(int status);

 protected:
  virtual void AbortJob(int status) = 0;
  std::vector<std::string> hosts_;  // every rank's, at rank 0
};

// Joins the job if an MPI launcher started this process as one of several; nullptr when
// it runs alone. Throws if several were started but vkpt was built without MPI (each
// would render the whole frame and write the same file).
std::unique_ptr<Cluster> JoinCluster(int* argc, char*** argv);

// "MPI (Open MPI v4.1.4, …)" or "none (built without MPI)", for --version.
std::string ClusterSupport();

}  // namespace vkpt::internal

// The cluster over MPI. Only the thread that joined calls MPI (MPI_THREAD_FUNNELED): rank 0
// renders its own chunks on another thread (chunk_dealer.cpp) and never calls MPI there.
#include <mpi.h>

#include <algorithm>
#include <cstring>

#include "cluster/cluster.h"
#include "cluster/launcher_env.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

// MPI counts in int: a message larger than this goes in parts.
constexpr uint64_t kMaxPart = uint64_t(1) << 30;

void Check(int code, const char* what) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw Error(std::string("MPI: ") + what + ": " + std::string(text, size_t(length)));
}

class MpiCluster final : public Cluster {
 public:
  MpiCluster(int* argc, char*** argv) {
    int provided = 0;
    Check(MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
    // Errors come back as codes (and become Errors), not as MPI's default abort.
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    char name[MPI_MAX_PROCESSOR_NAME];
    int length = 0;
    MPI_Get_processor_name(name, &length);
    host_.assign(name, size_t(length));
    hosts_ = Gather(host_);  // rank 0 names every rank; the others only name themselves
  }
  ~MpiCluster() override { MPI_Finalize(); }

  int Rank() const override { return rank_; }
  int Size() const override { return size_; }
  const std::string& Host() const override { return host_; }

  void Send(int to, int tag, std::span<const uint8_t> bytes) override {
    uint64_t n = bytes.size();
    Check(MPI_Send(&n, 1, MPI_UINT64_T, to, tag, MPI_COMM_WORLD), "MPI_Send");
    for (uint64_t at = 0; at < n; at += kMaxPart)
      Check(MPI_Send(bytes.data() + at, int(std::min(kMaxPart, n - at)), MPI_BYTE, to, tag, MPI_COMM_WORLD),
            "MPI_Send");
  }

  std::optional<Envelope> Poll(int from, int tag) override {
    int flag = 0;
    MPI_Status status;
    Check(MPI_Iprobe(from < 0 ? MPI_ANY_SOURCE : from, tag < 0 ? MPI_ANY_TAG : tag, MPI_COMM_WORLD, &flag, &status),
          "MPI_Iprobe");
    if (!flag) return std::nullopt;
    return Envelope{status.MPI_SOURCE, status.MPI_TAG};
  }

  std::vector<uint8_t> Receive(int from, int tag) override {
    uint64_t n = 0;
    Check(MPI_Recv(&n, 1, MPI_UINT64_T, from, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
    std::vector<uint8_t> bytes(n);
    for (uint64_t at = 0; at < n; at += kMaxPart)
      Check(MPI_Recv(bytes.data() + at, int(std::min(kMaxPart, n - at)), MPI_BYTE, from, tag, MPI_COMM_WORLD,
                     MPI_STATUS_IGNORE),
            "MPI_Recv");
    return bytes;
  }

  std::vector<std::string> Gather(const std::string& mine) override {
    int length = int(std::min<size_t>(mine.size(), 1 << 20));
    std::vector<int> lengths(rank_ == 0 ? size_ : 0);
    Check(MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Gather");
    std::vector<int> offsets(lengths.size());
    int total = 0;
    for (size_t r = 0; r < lengths.size(); ++r) {
      offsets[r] = total;
      total += lengths[r];
    }
    std::vector<char> all(size_t(total) + 1);
    Check(MPI_Gatherv(mine.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0,
                      MPI_COMM_WORLD),
          "MPI_Gatherv");
    std::vector<std::string> out;
    for (size_t r = 0; r < lengths.size(); ++r) out.emplace_back(all.data() + offsets[r], size_t(lengths[r]));
    return out;
  }

  bool AllEqual(uint64_t mine) override {
    uint64_t lo = 0, hi = 0;
    Check(MPI_Allreduce(&mine, &lo, 1, MPI_UINT64_T, MPI_MIN, MPI_COMM_WORLD), "MPI_Allreduce");
    Check(MPI_Allreduce(&mine, &hi, 1, MPI_UINT64_T, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
    return lo == hi;
  }

  int MaxOf(int mine) override {
    int out = 0;
    Check(MPI_Allreduce(&mine, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
    return out;
  }

  void AbortJob(int status) override { MPI_Abort(MPI_COMM_WORLD, status); }

 private:
  int rank_ = 0, size_ = 1;
  std::string host_;
};

}  // namespace

std::unique_ptr<Cluster> JoinCluster(int* argc, char*** argv) {
  if (LauncherProcessCount() <= 1) return nullptr;
  return std::make_unique<MpiCluster>(argc, argv);
}

std::string ClusterSupport() {
  char version[MPI_MAX_LIBRARY_VERSION_STRING];
  int length = 0;
  MPI_Get_library_version(version, &length);
  std::string v(version, size_t(length));
  v = v.substr(0, v.find_first_of(",\n"));
  return "MPI (" + v + ")";
}

}  // namespace vkpt::internal

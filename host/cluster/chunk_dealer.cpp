#include "cluster/chunk_dealer.h"

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "util/error.h"

namespace vkpt::internal {
namespace {

// The protocol: a rank sends kRequest and gets kAssign (a chunk index, or kNoChunk, and
// the active pixels when they changed since its last chunk), then sends the chunk's sums
// as kResult and asks again; kFailure carries a rank's error. A request made while every
// chunk before the next decision point is out waits for that decision.
enum Tag : int { kRequest = 1, kAssign, kResult, kFailure };
constexpr uint32_t kNoChunk = 0xFFFFFFFFu;
constexpr uint32_t kNotYet = 0xFFFFFFFEu;  // none before the next decision (never sent)

using ActivePixels = std::shared_ptr<const std::vector<uint8_t>>;

// kAssign: the chunk, whether the active pixels follow, and those.
std::vector<uint8_t> AssignmentMessage(uint32_t chunk, const std::vector<uint8_t>* active) {
  const uint32_t head[2] = {chunk, active ? 1u : 0u};
  std::vector<uint8_t> bytes(sizeof head + (active ? active->size() : 0));
  std::memcpy(bytes.data(), head, sizeof head);
  if (active && !active->empty()) std::memcpy(bytes.data() + sizeof head, active->data(), active->size());
  return bytes;
}

uint32_t ReadAssignment(const std::vector<uint8_t>& bytes, std::vector<uint8_t>& active) {
  uint32_t head[2];
  if (bytes.size() < sizeof head) throw Error("MPI: an assignment message is truncated");
  std::memcpy(head, bytes.data(), sizeof head);
  if (head[1]) active.assign(bytes.begin() + sizeof head, bytes.end());
  return head[0];
}

double Since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A whole number from the environment, or `otherwise`.
long EnvironmentNumber(const char* name, long otherwise) {
  const char* v = std::getenv(name);
  return v && *v ? std::strtol(v, nullptr, 10) : otherwise;
}

[[noreturn]] void Fail(Cluster& cluster, int rank, const std::string& what) {
  std::fprintf(stderr, "vkpt: error: %s: %s\n", cluster.Name(rank).c_str(), what.c_str());
  std::fflush(stderr);
  cluster.Abort(1);
}

}  // namespace

ChunkRenderer ChunkRendererOf(FrameRenderer& frame, const ChunkPlan& plan) {
  const long delayMs = EnvironmentNumber("VKPT_TEST_CHUNK_DELAY_MS", 0);
  const long failAfter = EnvironmentNumber("VKPT_TEST_FAIL_AFTER_CHUNKS", -1);
  auto rendered = std::make_shared<long>(0);
  return [&frame, plan, delayMs, failAfter, rendered](uint32_t chunk, std::span<const uint8_t> active) {
    if ((*rendered)++ == failAfter)
      throw Error("failing at chunk " + std::to_string(chunk) + " (VKPT_TEST_FAIL_AFTER_CHUNKS)");
    if (delayMs > 0) std::this_thread::sleep_for(std::chrono::milliseconds(delayMs));
    frame.Clear();
    frame.AddSamples(plan.Begin(chunk), plan.Samples(chunk), active, {});
    return frame.Sums();
  };
}

// Rank 0's own renderer and the count of chunks dealt: it takes chunks from the same
// count as the other ranks, on a thread that never calls MPI.
class ChunkDealer::LocalRenderer {
 public:
  LocalRenderer(const ChunkPlan& plan, const ChunkRenderer& render, ActivePixels active)
      : plan_(plan), render_(render), limit_(0), active_(std::move(active)) {
    thread_ = std::thread([this] { Run(); });
  }
  ~LocalRenderer() {
    StopDealing();
    thread_.join();
  }

  // The next chunk to deal, kNoChunk, or kNotYet.
  uint32_t Deal() {
    std::lock_guard<std::mutex> lock(mutex_);
    return DealLocked();
  }
  // Chunks before `limit` may be dealt, sampling the pixels `active` marks.
  void Open(uint32_t limit, ActivePixels active) {
    std::lock_guard<std::mutex> lock(mutex_);
    limit_ = limit;
    active_ = std::move(active);
    dealable_.notify_all();
  }
  void StopDealing() {
    std::lock_guard<std::mutex> lock(mutex_);
    dealing_ = false;
    dealable_.notify_all();
  }
  // Chunks rank 0 has finished since the last call; its error, if it failed.
  std::map<uint32_t, FrameSums> TakeFinished(std::optional<std::string>* error) {
    std::lock_guard<std::mutex> lock(mutex_);
    *error = error_;
    return std::exchange(finished_, {});
  }
  // Whether chunk `chunk` will never be dealt: past the plan, or not dealt yet and no more
  // dealing (stopped, or the limit reached).
  bool NeverDealt(uint32_t chunk) {
    std::lock_guard<std::mutex> lock(mutex_);
    return chunk >= plan_.Chunks() || (chunk >= next_ && (!dealing_ || next_ >= limit_));
  }
  bool Done() {
    std::lock_guard<std::mutex> lock(mutex_);
    return done_;
  }
  uint32_t chunks = 0;
  double seconds = 0.0;

 private:
  uint32_t DealLocked() {
    if (!dealing_ || next_ >= plan_.Chunks()) return kNoChunk;
    if (next_ >= limit_) return kNotYet;
    return next_++;
  }
  void Run() {
    try {
      for (;;) {
        std::unique_lock<std::mutex> lock(mutex_);
        uint32_t c = kNotYet;
        dealable_.wait(lock, [&] { return (c = DealLocked()) != kNotYet; });
        if (c == kNoChunk) break;
        const ActivePixels active = active_;
        lock.unlock();
        const auto t0 = std::chrono::steady_clock::now();
        FrameSums sums = render_(c, *active);
        seconds += Since(t0);
        ++chunks;
        lock.lock();
        finished_.emplace(c, std::move(sums));
      }
    } catch (const std::exception& e) {
      std::lock_guard<std::mutex> lock(mutex_);
      error_ = e.what();
    }
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
  }

  const ChunkPlan plan_;
  const ChunkRenderer& render_;
  std::mutex mutex_;
  std::condition_variable dealable_;
  uint32_t next_ = 0, limit_;
  ActivePixels active_;
  bool dealing_ = true, done_ = false;
  std::map<uint32_t, FrameSums> finished_;
  std::optional<std::string> error_;
  std::thread thread_;
};

ChunkDealer::ChunkDealer(Cluster& cluster, const ChunkPlan& plan, const ChunkRenderer& render)
    : cluster_(cluster),
      plan_(plan),
      active_(std::make_shared<const std::vector<uint8_t>>()),
      sent_(cluster.Size(), active_),
      ranks_(cluster.Size()) {
  for (int r = 0; r < cluster.Size(); ++r) ranks_[r].name = cluster.Name(r);
  local_ = std::make_unique<LocalRenderer>(plan_, render, active_);
}

ChunkDealer::~ChunkDealer() = default;

void ChunkDealer::Open(uint32_t limit, const std::vector<uint8_t>& active) {
  if (active != *active_) active_ = std::make_shared<const std::vector<uint8_t>>(active);
  local_->Open(std::min(limit, plan_.Chunks()), active_);
}

bool ChunkDealer::Assign(int rank) {
  const uint32_t c = local_->Deal();
  if (c == kNotYet) return false;
  if (c == kNoChunk) ++told_;
  const bool changed = c != kNoChunk && sent_[rank] != active_;
  cluster_.Send(rank, kAssign, AssignmentMessage(c, changed ? active_.get() : nullptr));
  sent_[rank] = active_;
  return true;
}

bool ChunkDealer::Serve() {
  bool busy = false;
  if (std::optional<Cluster::Envelope> e = cluster_.Poll()) {
    busy = true;
    const std::vector<uint8_t> bytes = cluster_.Receive(e->from, e->tag);
    if (e->tag == kRequest) {
      if (!Assign(e->from)) waiting_.push_back(e->from);
    } else if (e->tag == kResult) {
      uint32_t c = 0;
      double seconds = 0.0;
      FrameSums sums = DecodeChunk(bytes, &c, &seconds);
      pending_.emplace(c, std::move(sums));
      ++ranks_[e->from].chunks;
      ranks_[e->from].renderSeconds += seconds;
      ranks_[e->from].bytesSent += bytes.size();
    } else if (e->tag == kFailure) {
      Fail(cluster_, e->from, std::string(bytes.begin(), bytes.end()));
    }
  }
  std::optional<std::string> error;
  pending_.merge(local_->TakeFinished(&error));
  if (error) Fail(cluster_, 0, *error);
  while (!waiting_.empty() && Assign(waiting_.front())) waiting_.erase(waiting_.begin());
  return busy;
}

std::optional<FrameSums> ChunkDealer::Next(const std::function<bool()>& stopDealing) {
  for (;;) {
    if (auto it = pending_.find(next_); it != pending_.end()) {
      FrameSums sums = std::move(it->second);
      pending_.erase(it);
      ++next_;
      return sums;
    }
    if (local_->NeverDealt(next_)) return std::nullopt;
    if (stopDealing && stopDealing()) local_->StopDealing();
    if (!Serve()) std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
}

std::vector<RankShare> ChunkDealer::Finish() {
  local_->StopDealing();
  while (told_ < cluster_.Size() - 1 || !local_->Done())
    if (!Serve()) std::this_thread::sleep_for(std::chrono::microseconds(200));
  ranks_[0].chunks = local_->chunks;
  ranks_[0].renderSeconds = local_->seconds;
  return ranks_;
}

void RenderDealtChunks(Cluster& cluster, const ChunkRenderer& render) {
  std::vector<uint8_t> active;  // empty: every pixel
  for (;;) {
    cluster.Send(0, kRequest, {});
    cluster.Wait(0, kAssign);
    const uint32_t c = ReadAssignment(cluster.Receive(0, kAssign), active);
    if (c == kNoChunk) return;
    std::vector<uint8_t> result;
    try {
      const auto t0 = std::chrono::steady_clock::now();
      FrameSums sums = render(c, active);
      result = EncodeChunk(c, sums, Since(t0));
    } catch (const std::exception& e) {
      const std::string what = e.what();
      cluster.Send(0, kFailure, {reinterpret_cast<const uint8_t*>(what.data()), what.size()});
      cluster.Wait(0, kAssign);  // rank 0 ends the job
    }
    cluster.Send(0, kResult, result);
  }
}

}  // namespace vkpt::internal

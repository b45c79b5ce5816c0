#include "dist/chunk_dealer.h"

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "image/chunked_frame.h"
#include "util/error.h"

namespace vkpt {
namespace {

// The protocol: a rank sends kRequest and gets kAssign (a chunk index, or kNoChunk, and
// the active pixels when they changed since its last chunk), then sends the chunk's sums
// as kResult and asks again; kFailure carries a rank's error. A request made while every
// chunk before the next decision point is out waits for that decision.
enum Tag : int { kRequest = 1, kAssign, kResult, kFailure };
constexpr uint32_t kNoChunk = 0xFFFFFFFFu;
constexpr uint32_t kNotYet = 0xFFFFFFFEu;  // none before the next decision (never sent)

using ActivePixels = std::shared_ptr<const std::vector<uint8_t>>;

struct ChunkHeader {
  uint32_t chunk, width, height;
  uint32_t valueBytes;  // of each sum: 4 (float) or 8 (double)
  uint64_t rays, nonFinite, cutShort;
  double seconds;
};

// A pixel as sent: Σf and Σf² (six values) and its sample count.
size_t PixelBytes(uint32_t valueBytes) { return 6 * size_t(valueBytes) + sizeof(uint32_t); }

// Whether every sum is a float exactly (a GPU's are): then they go as floats, at half the
// bytes, and come back as the same doubles.
bool AllFloats(const FrameSums& sums) {
  for (const PixelSums& p : sums.pixels)
    for (int c = 0; c < 3; ++c)
      if (double(float(p.sum[c])) != p.sum[c] || double(float(p.sumOfSquares[c])) != p.sumOfSquares[c]) return false;
  return true;
}

template <typename T>
void PutPixels(const FrameSums& sums, uint8_t* at) {
  for (const PixelSums& p : sums.pixels) {
    const T v[6] = {T(p.sum.x), T(p.sum.y), T(p.sum.z), T(p.sumOfSquares.x), T(p.sumOfSquares.y), T(p.sumOfSquares.z)};
    std::memcpy(at, v, sizeof v);
    std::memcpy(at + sizeof v, &p.samples, sizeof p.samples);
    at += PixelBytes(sizeof(T));
  }
}

template <typename T>
void GetPixels(const uint8_t* at, FrameSums& sums) {
  for (PixelSums& p : sums.pixels) {
    T v[6];
    std::memcpy(v, at, sizeof v);
    std::memcpy(&p.samples, at + sizeof v, sizeof p.samples);
    p.sum = {v[0], v[1], v[2]};
    p.sumOfSquares = {v[3], v[4], v[5]};
    at += PixelBytes(sizeof(T));
  }
}

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

[[noreturn]] void Fail(Cluster& cluster, int rank, const std::string& what) {
  std::fprintf(stderr, "vkpt: error: %s: %s\n", cluster.Name(rank).c_str(), what.c_str());
  std::fflush(stderr);
  cluster.Abort(1);
}

// Rank 0's own renderer and the count of chunks dealt: it takes chunks from the same
// count as the other ranks, on a thread that never calls MPI.
class LocalRenderer {
 public:
  LocalRenderer(const ChunkPlan& plan, const ChunkRenderer& render, uint32_t limit, ActivePixels active)
      : plan_(plan), render_(render), limit_(limit), active_(std::move(active)) {
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
  uint32_t Dealt() {
    std::lock_guard<std::mutex> lock(mutex_);
    return next_;
  }
  // Chunks rank 0 has finished since the last call; its error, if it failed.
  std::map<uint32_t, FrameSums> TakeFinished(std::optional<std::string>* error) {
    std::lock_guard<std::mutex> lock(mutex_);
    *error = error_;
    return std::exchange(finished_, {});
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

}  // namespace

std::vector<uint8_t> EncodeChunk(uint32_t chunk, const FrameSums& sums, double seconds) {
  const uint32_t valueBytes = AllFloats(sums) ? sizeof(float) : sizeof(double);
  const ChunkHeader h{chunk, sums.width, sums.height, valueBytes, sums.rays, sums.nonFinite, sums.cutShort, seconds};
  std::vector<uint8_t> bytes(sizeof h + sums.pixels.size() * PixelBytes(valueBytes));
  std::memcpy(bytes.data(), &h, sizeof h);
  if (valueBytes == sizeof(float)) PutPixels<float>(sums, bytes.data() + sizeof h);
  else PutPixels<double>(sums, bytes.data() + sizeof h);
  return bytes;
}

FrameSums DecodeChunk(const std::vector<uint8_t>& bytes, uint32_t* chunk, double* seconds) {
  ChunkHeader h;
  if (bytes.size() < sizeof h) throw Error("MPI: a chunk's message is truncated");
  std::memcpy(&h, bytes.data(), sizeof h);
  const uint64_t pixels = uint64_t(h.width) * h.height;
  if ((h.valueBytes != sizeof(float) && h.valueBytes != sizeof(double)) ||
      bytes.size() != sizeof h + pixels * PixelBytes(h.valueBytes))
    throw Error("MPI: a chunk's message has the wrong size");
  FrameSums s;
  s.width = h.width;
  s.height = h.height;
  s.rays = h.rays;
  s.nonFinite = h.nonFinite;
  s.cutShort = h.cutShort;
  s.pixels.resize(pixels);
  if (h.valueBytes == sizeof(float)) GetPixels<float>(bytes.data() + sizeof h, s);
  else GetPixels<double>(bytes.data() + sizeof h, s);
  *chunk = h.chunk;
  *seconds = h.seconds;
  return s;
}

DealtFrame DealChunks(Cluster& cluster, const ChunkPlan& plan, const ChunkRenderer& render, const DealerHooks& hooks) {
  DealtFrame out;
  out.ranks.resize(cluster.Size());
  for (int r = 0; r < cluster.Size(); ++r) out.ranks[r].name = cluster.Name(r);
  // The next decision point, and the chunks before it.
  const Decisions& decisions = hooks.decisions;
  uint32_t point = decisions.nextPoint ? decisions.nextPoint(0) : UINT32_MAX;
  auto chunksBefore = [&plan](uint32_t spp) {
    return uint32_t(std::min<uint64_t>(plan.Chunks(), (uint64_t(spp) + plan.chunkSpp - 1) / plan.chunkSpp));
  };
  std::map<uint32_t, FrameSums> pending;  // arrived out of order
  int told = 0;                           // ranks told there are no more chunks
  std::vector<int> waiting;               // ranks whose request waits for a decision
  // The pixels the chunks dealt now sample (empty: every pixel), and those each rank has.
  ActivePixels active = std::make_shared<const std::vector<uint8_t>>();
  std::vector<ActivePixels> sent(cluster.Size(), active);
  const auto t0 = std::chrono::steady_clock::now();
  double lastCheckpoint = 0.0;
  LocalRenderer local(plan, render, chunksBefore(point), active);
  auto assign = [&](int rank) {
    const uint32_t c = local.Deal();
    if (c == kNotYet) return false;
    if (c == kNoChunk) ++told;
    const bool changed = c != kNoChunk && sent[rank] != active;
    cluster.Send(rank, kAssign, AssignmentMessage(c, changed ? active.get() : nullptr));
    sent[rank] = active;
    return true;
  };
  for (;;) {
    bool busy = false;
    if (std::optional<Cluster::Envelope> e = cluster.Poll()) {
      busy = true;
      const std::vector<uint8_t> bytes = cluster.Receive(e->from, e->tag);
      if (e->tag == kRequest) {
        if (!assign(e->from)) waiting.push_back(e->from);
      } else if (e->tag == kResult) {
        uint32_t c = 0;
        double seconds = 0.0;
        FrameSums sums = DecodeChunk(bytes, &c, &seconds);
        pending.emplace(c, std::move(sums));
        ++out.ranks[e->from].chunks;
        out.ranks[e->from].renderSeconds += seconds;
        out.ranks[e->from].bytesSent += bytes.size();
      } else if (e->tag == kFailure) {
        Fail(cluster, e->from, std::string(bytes.begin(), bytes.end()));
      }
    }
    std::optional<std::string> error;
    pending.merge(local.TakeFinished(&error));
    if (error) Fail(cluster, 0, *error);
    for (auto it = pending.find(out.chunks); it != pending.end(); it = pending.find(out.chunks)) {
      AddChunk(out.sums, it->second);
      out.spp += plan.Samples(out.chunks);
      ++out.chunks;
      pending.erase(it);
      busy = true;
      if (hooks.progress) hooks.progress(double(out.chunks) / plan.Chunks());
      if (out.spp == point) {  // every chunk dealt has been added
        std::vector<uint8_t> next = *active;
        if (decisions.decide(out.sums, out.spp, next)) {
          out.decidedToStop = true;
          local.StopDealing();
          break;
        }
        point = decisions.nextPoint(out.spp);
        active = std::make_shared<const std::vector<uint8_t>>(std::move(next));
        local.Open(chunksBefore(point), active);
      }
      if (hooks.checkpoint && hooks.checkpointSeconds > 0.0 && Since(t0) - lastCheckpoint >= hooks.checkpointSeconds &&
          out.chunks < plan.Chunks()) {
        hooks.checkpoint(out.sums, out.spp);
        lastCheckpoint = Since(t0);
      }
    }
    if (hooks.stopDealing && hooks.stopDealing()) local.StopDealing();
    while (!waiting.empty() && assign(waiting.front())) waiting.erase(waiting.begin());
    if (told == cluster.Size() - 1 && local.Done() && out.chunks == local.Dealt()) break;
    if (!busy) std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  out.ranks[0].chunks = local.chunks;
  out.ranks[0].renderSeconds = local.seconds;
  return out;
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

}  // namespace vkpt

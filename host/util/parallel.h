// vkpt's one way of running work on several threads: the BVH builder, the CPU renderer
// and vkpt-bench all use these helpers. Threads are started per call, for work coarse
// enough to pay for that (a large node, a subtree, an image, a ray set). An exception
// thrown on any thread (std::bad_alloc, say, or failing to start a thread) is rethrown
// on the calling thread once all have joined: none ends the process.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace vkpt::internal {

// The first exception thrown by any of a group of threads, to rethrow after they join.
class FirstException {
 public:
  template <class F>
  void Run(F&& f) noexcept {
    try {
      f();
    } catch (...) {
      std::lock_guard lock(mutex_);
      if (!error_) error_ = std::current_exception();
      failed_ = true;
    }
  }
  bool Failed() const { return failed_; }
  void Rethrow() {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  std::mutex mutex_;
  std::exception_ptr error_;
  std::atomic<bool> failed_{false};
};

// `requested` threads, or all cores for 0 (the convention of every --threads option).
inline unsigned ThreadCount(unsigned requested) {
  return requested ? requested : std::max(1u, std::thread::hardware_concurrency());
}

// Runs f(t) for every t in [0, threads) at once: f(0) on the calling thread, the others
// on threads started for them; returns when all have returned, rethrowing the first
// exception recorded in `error`. Long-running f's may poll error.Failed() to stop early
// once another has thrown. If a thread cannot be started, f(0) is not run.
template <class F>
void RunThreads(unsigned threads, FirstException& error, F&& f) {
  std::vector<std::thread> pool;
  error.Run([&] {
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back([&f, &error, t] { error.Run([&] { f(t); }); });
  });
  if (!error.Failed()) error.Run([&] { f(0u); });
  for (auto& th : pool) th.join();
  error.Rethrow();
}

template <class F>
void RunThreads(unsigned threads, F&& f) {
  FirstException error;
  RunThreads(threads, error, f);
}

// Runs f(begin, end, chunk) over [first, first + count) split into `threads` chunks.
template <class F>
void ForChunks(uint32_t first, uint32_t count, unsigned threads, F&& f) {
  const uint32_t per = (count + threads - 1) / threads;
  RunThreads(threads, [&](unsigned t) {
    f(first + std::min(count, t * per), first + std::min(count, (t + 1) * per), t);
  });
}

// Runs f(k) for k in [0, n) on up to `threads` threads, each taking the next `grain`
// indices at a time (more than one where a single f is too short to pay for the shared
// counter); after an exception no further k is started.
template <class F>
void ParallelFor(size_t n, unsigned threads, F&& f, size_t grain = 1) {
  FirstException error;
  std::atomic<size_t> next{0};
  const size_t blocks = (n + grain - 1) / grain;
  RunThreads(unsigned(std::min<size_t>(threads, blocks)), error, [&](unsigned) {
    for (size_t b; !error.Failed() && (b = next.fetch_add(grain)) < n;)
      for (size_t k = b; k < std::min(n, b + grain); ++k) f(k);
  });
}

// ParallelFor(n, threads, f) while the calling thread calls progress(fraction of the k
// done) about every 100 ms, and progress(1) at the end; the work runs on `threads`
// threads of its own.
template <class F>
void ParallelForWithProgress(size_t n, unsigned threads, F&& f, const std::function<void(double)>& progress) {
  FirstException error;
  std::atomic<size_t> done{0};
  RunThreads(2, error, [&](unsigned t) {
    if (t == 1) {
      return ParallelFor(n, threads, [&](size_t k) {
        if (error.Failed()) return;  // the progress callback threw
        f(k);
        done.fetch_add(1);
      });
    }
    while (done.load() < n && !error.Failed()) {
      progress(double(done.load()) / double(n));
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  });
  progress(1.0);
}

}  // namespace vkpt::internal

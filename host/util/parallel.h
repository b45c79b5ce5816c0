// Two ways of spreading a loop over threads, for work that is coarse enough to pay for
// starting them (the BVH builder's large nodes and subtrees). An exception thrown on any
// thread (std::bad_alloc, say) is rethrown on the calling thread once all have joined.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace vkpt {

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

// Runs f(begin, end, chunk) over [first, first + count) split into `threads` chunks.
template <class F>
void ForChunks(uint32_t first, uint32_t count, unsigned threads, F&& f) {
  FirstException error;
  std::vector<std::thread> pool;
  const uint32_t per = (count + threads - 1) / threads;
  for (unsigned t = 1; t < threads; ++t) {
    uint32_t b = first + std::min(count, t * per), e = first + std::min(count, (t + 1) * per);
    pool.emplace_back([&f, &error, b, e, t] { error.Run([&] { f(b, e, t); }); });
  }
  error.Run([&] { f(first, first + std::min(count, per), 0u); });
  for (auto& th : pool) th.join();
  error.Rethrow();
}

// Runs f(k) for k in [0, n) on up to `threads` threads, each taking the next k; after an
// exception no further k is started.
template <class F>
void ParallelFor(size_t n, unsigned threads, F&& f) {
  FirstException error;
  std::atomic<size_t> next{0};
  auto worker = [&] {
    error.Run([&] {
      for (size_t k; !error.Failed() && (k = next.fetch_add(1)) < n;) f(k);
    });
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < std::min<size_t>(threads, n); ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  error.Rethrow();
}

}  // namespace vkpt

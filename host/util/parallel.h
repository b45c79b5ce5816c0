// Two ways of spreading a loop over threads, for work that is coarse enough to pay for
// starting them (the BVH builder's large nodes and subtrees).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <thread>
#include <vector>

namespace vkpt {

// Runs f(begin, end, chunk) over [first, first + count) split into `threads` chunks.
template <class F>
void ForChunks(uint32_t first, uint32_t count, unsigned threads, F&& f) {
  std::vector<std::thread> pool;
  const uint32_t per = (count + threads - 1) / threads;
  for (unsigned t = 1; t < threads; ++t) {
    uint32_t b = first + std::min(count, t * per), e = first + std::min(count, (t + 1) * per);
    pool.emplace_back([&f, b, e, t] { f(b, e, t); });
  }
  f(first, first + std::min(count, per), 0u);
  for (auto& th : pool) th.join();
}

// Runs f(k) for k in [0, n) on up to `threads` threads, each taking the next k.
template <class F>
void ParallelFor(size_t n, unsigned threads, F&& f) {
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t k; (k = next.fetch_add(1)) < n;) f(k);
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < std::min<size_t>(threads, n); ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
}

}  // namespace vkpt

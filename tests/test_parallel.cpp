// The thread helpers: every index runs once, and an exception on any thread reaches the
// caller (a worker thread's exception would otherwise end the process).
#include <gtest/gtest.h>

#include <atomic>
#include <new>
#include <stdexcept>
#include <vector>

#include "util/parallel.h"

namespace vkpt {
namespace {

TEST(Parallel, ForVisitsEveryIndexOnce) {
  for (unsigned threads : {1u, 2u, 5u}) {
    std::vector<std::atomic<int>> seen(1000);
    ParallelFor(seen.size(), threads, [&](size_t k) { seen[k]++; });
    for (const auto& s : seen) EXPECT_EQ(s.load(), 1);
    std::vector<std::atomic<int>> chunks(1001);
    ForChunks(0, uint32_t(chunks.size()), threads, [&](uint32_t b, uint32_t e, unsigned) {
      for (uint32_t i = b; i < e; ++i) chunks[i]++;
    });
    for (const auto& s : chunks) EXPECT_EQ(s.load(), 1);
  }
}

TEST(Parallel, ExceptionsOnAnyThreadReachTheCaller) {
  for (unsigned threads : {1u, 2u, 5u}) {
    EXPECT_THROW(ParallelFor(1000, threads,
                             [](size_t k) {
                               if (k == 777) throw std::bad_alloc();
                             }),
                 std::bad_alloc);
    // The last chunk runs on a worker thread whenever there is more than one.
    EXPECT_THROW(ForChunks(0, 1000, threads,
                           [](uint32_t, uint32_t e, unsigned) {
                             if (e == 1000) throw std::runtime_error("chunk failed");
                           }),
                 std::runtime_error);
  }
}

}  // namespace
}  // namespace vkpt

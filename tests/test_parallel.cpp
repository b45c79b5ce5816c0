// The thread helpers and their users: every index runs once, and an exception on any
// thread reaches the caller (a worker thread's exception would otherwise end the process).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <stdexcept>
#include <thread>
#include <vector>

#include "cpu/path_tracer.h"
#include "gltf/gltf_loader.h"
#include "test_util.h"
#include "util/parallel.h"

namespace vkpt::internal {
namespace {

// While armed, every allocation fails (std::bad_alloc) on threads other than the one
// that armed it: a worker's out-of-memory on demand. See operator new below.
std::atomic<bool> gFailOtherThreads{false};
std::thread::id gArmedBy;

struct FailAllocationsOnOtherThreads {
  FailAllocationsOnOtherThreads() {
    gArmedBy = std::this_thread::get_id();
    gFailOtherThreads = true;
  }
  ~FailAllocationsOnOtherThreads() { gFailOtherThreads = false; }
};

}  // namespace
}  // namespace vkpt::internal

void* operator new(std::size_t size) {
  if (vkpt::internal::gFailOtherThreads.load(std::memory_order_relaxed) &&
      std::this_thread::get_id() != vkpt::internal::gArmedBy)
    throw std::bad_alloc();
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
// The nothrow form too: code that allocates with it (LLVM inside lavapipe) frees with the
// plain operator delete below, so both must come from malloc — under AddressSanitizer a
// nothrow new of its own would be freed here with free(), an alloc-dealloc mismatch.
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return ::operator new(size);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
// Not inlined: inlined into std::allocator, GCC 12 would see free() on memory from
// operator new and warn (-Wmismatched-new-delete), not knowing this new is malloc.
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace vkpt::internal {
namespace {

TEST(Parallel, ForVisitsEveryIndexOnce) {
  for (unsigned threads : {1u, 2u, 5u}) {
    for (size_t grain : {size_t(1), size_t(7)}) {
      std::vector<std::atomic<int>> seen(1000);
      ParallelFor(seen.size(), threads, [&](size_t k) { seen[k]++; }, grain);
      for (const auto& s : seen) EXPECT_EQ(s.load(), 1);
    }
    std::vector<std::atomic<int>> chunks(1001);
    ForChunks(0, uint32_t(chunks.size()), threads, [&](uint32_t b, uint32_t e, unsigned) {
      for (uint32_t i = b; i < e; ++i) chunks[i]++;
    });
    for (const auto& s : chunks) EXPECT_EQ(s.load(), 1);
    std::vector<double> reported;
    std::vector<std::atomic<int>> rows(100);
    ParallelForWithProgress(
        rows.size(), threads, [&](size_t k) { rows[k]++; }, [&](double f) { reported.push_back(f); });
    for (const auto& s : rows) EXPECT_EQ(s.load(), 1);
    ASSERT_FALSE(reported.empty());
    EXPECT_EQ(reported.back(), 1.0);
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
    // The work runs on threads of its own; the progress reports must stop too.
    EXPECT_THROW(ParallelForWithProgress(
                     1000, threads,
                     [](size_t k) {
                       if (k == 777) throw std::bad_alloc();
                     },
                     [](double) {}),
                 std::bad_alloc);
  }
}

// A RenderScene whose CPU tree is a chain of 100 wide nodes, each with the next node and
// empty leaves as its other children, every box covering everything: every ray defers
// 700 leaves, more than the traversal's inline stack holds, so it allocates (and the leaves
// hold nothing, so every ray misses).
RenderScene ChainScene() {
  RenderScene rs = PrepareRenderScene(LoadGltf(test::SourcePath("scenes/cornell.gltf")));
  constexpr uint32_t kNodes = 100, kEmptyLeaf = (0u << 4) | 1u;
  rs.wideLayout = {};
  rs.wideLayout.packets.resize(1);
  for (uint32_t& index : rs.wideLayout.packets[0].index) index = shader::kInvalidIndex;
  for (uint32_t i = 0; i < kNodes; ++i) {
    BvhWideNode n{};
    for (int k = 0; k < kBvhWidth; ++k) {
      for (int axis = 0; axis < 3; ++axis) n.lo[axis][k] = -1e30f, n.hi[axis][k] = 1e30f;
      n.child[k] = kEmptyLeaf;
    }
    n.child[0] = i + 1 < kNodes ? (i + 1) << 4 : kEmptyLeaf;
    rs.wideLayout.nodes.push_back(n);
  }
  return rs;
}

TEST(Parallel, CpuRendererPassesAWorkersExceptionToTheCaller) {
  const RenderScene rs = ChainScene();
  shader::FrameParams p = MakeFrameParams(rs, DefaultCamera(Bounds3f{{-1, -1, -1}, {1, 1, 1}}), 8, 8);
  p.sampleCount = 1;
  p.maxDepth = 4;
  CpuRenderOptions options;
  options.threads = 1;
  EXPECT_EQ(RenderCpu(rs, p, options).image.pixels.size(), 64u);  // the scene renders
  // With progress reports the calling thread only reports; the rows run on a worker,
  // whose traversal stack cannot grow.
  options.progress = [](double) {};
  FailAllocationsOnOtherThreads fail;
  EXPECT_THROW(RenderCpu(rs, p, options), std::bad_alloc);
}

TEST(Parallel, CpuRendererPassesAProgressCallbacksExceptionToTheCaller) {
  const RenderScene rs = PrepareRenderScene(LoadGltf(test::SourcePath("scenes/cornell.gltf")));
  shader::FrameParams p = MakeFrameParams(rs, DefaultCamera(Bounds3f{{-1, -1, -1}, {1, 1, 1}}), 16, 16);
  p.sampleCount = 1;
  p.maxDepth = 4;
  CpuRenderOptions options;
  options.threads = 2;
  options.progress = [](double) { throw std::runtime_error("progress display failed"); };
  EXPECT_THROW(RenderCpu(rs, p, options), std::runtime_error);
}

}  // namespace
}  // namespace vkpt::internal

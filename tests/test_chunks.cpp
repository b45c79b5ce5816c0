// Samples in chunks (image/chunked_frame.h), in process: a chunked render cut into any
// passes equals its chunks rendered on separate frames, in any order, and added in chunk
// order — the identity an MPI job's merge relies on — on both backends. On the CPU, whose
// chunk sums are doubles, adding in another order changes bits: the order is what makes
// the identity. (The GPU's chunk sums are floats, which a few double additions add
// exactly in any order.)
#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <memory>
#include <vector>

#include "cpu/path_tracer.h"
#include "gpu_test.h"
#include "image/chunked_frame.h"
#include "render/render_scene.h"
#include "scene/gltf_loader.h"
#include "test_util.h"
#include "util/error.h"
#include "vk/vk_renderer.h"

namespace vkpt {
namespace {

struct Cornell {
  Scene scene = LoadGltf(test::SourcePath("scenes/cornell.gltf"));
  RenderScene cpu = PrepareRenderScene(scene);
  RenderScene gpu = PrepareRenderScene(scene, {.directionCopies = true}, false);
  shader::FrameParams Frame() const {
    shader::FrameParams p = MakeFrameParams(cpu, scene.cameras[0], 20, 20);
    p.seed = 11;
    p.maxDepth = 32;
    p.rrDepth = 3;
    return p;
  }
};

const Cornell& TheCornellBox() {
  static const Cornell c;
  return c;
}

bool SameBits(const FrameSums& a, const FrameSums& b) {
  if (a.pixels.size() != b.pixels.size() || a.rays != b.rays || a.nonFinite != b.nonFinite) return false;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const PixelSums &p = a.pixels[i], &q = b.pixels[i];
    if (p.samples != q.samples || std::memcmp(&p.sum, &q.sum, sizeof p.sum) != 0 ||
        std::memcmp(&p.sumOfSquares, &q.sumOfSquares, sizeof p.sumOfSquares) != 0)
      return false;
  }
  return true;
}

// 22 samples in chunks of 8: passes of 3, 9 and 10 (cutting chunks 0 and 1 and ending in
// the unfinished chunk 2) against chunks 2, 0 and 1 rendered on their own frames.
void ExpectChunksMergeInOrder(const std::function<std::unique_ptr<FrameRenderer>()>& begin, bool orderMatters) {
  constexpr uint32_t kChunk = 8;
  ChunkedFrame chunked(begin(), kChunk);
  chunked.AddSamples(0, 3, {}, {});
  chunked.AddSamples(3, 9, {}, {});
  chunked.AddSamples(12, 10, {}, {});
  std::vector<FrameSums> chunks(3);
  for (uint32_t c : {2u, 0u, 1u}) {
    auto frame = begin();
    frame->AddSamples(c * kChunk, c == 2 ? 6 : kChunk, {}, {});
    chunks[c] = frame->Sums();
  }
  FrameSums inOrder, reversed;
  for (int c = 0; c < 3; ++c) AddChunk(inOrder, chunks[c]);
  for (int c = 2; c >= 0; --c) AddChunk(reversed, chunks[c]);
  const FrameSums sums = chunked.Sums();
  EXPECT_TRUE(SameBits(sums, inOrder));
  if (orderMatters) {
    EXPECT_FALSE(SameBits(sums, reversed)) << "the chunk order never mattered: no teeth";
  }
  for (const PixelSums& p : sums.pixels) ASSERT_EQ(p.samples, 22u);

  // One chunk is summed exactly as an unchunked frame sums it; Clear starts again.
  auto plain = begin();
  plain->AddSamples(0, kChunk, {}, {});
  chunked.Clear();
  chunked.AddSamples(0, kChunk, {}, {});
  EXPECT_TRUE(SameBits(chunked.Sums(), plain->Sums()));
}

TEST(Chunks, CpuChunksMergeInChunkOrder) {
  const Cornell& c = TheCornellBox();
  ExpectChunksMergeInOrder([&] { return BeginCpuFrame(c.cpu, c.Frame()); }, true);
}

class ChunksGpu : public test::ValidatedGpuTest {};

TEST_F(ChunksGpu, ChunksMergeInChunkOrder) {
  const Cornell& c = TheCornellBox();
  vk::GpuRenderer gpu(test::Gpu(), c.gpu);
  ExpectChunksMergeInOrder([&] { return gpu.BeginFrame(c.Frame()); }, false);
}

TEST(Chunks, PassesMustFollowEachOther) {
  const Cornell& c = TheCornellBox();
  ChunkedFrame chunked(BeginCpuFrame(c.cpu, c.Frame()), 4);
  chunked.AddSamples(0, 2, {}, {});
  EXPECT_THROW(chunked.AddSamples(0, 2, {}, {}), Error);
  EXPECT_THROW(ChunkedFrame(BeginCpuFrame(c.cpu, c.Frame()), 0), Error);
}

}  // namespace
}  // namespace vkpt

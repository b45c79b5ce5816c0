// Samples in chunks: a frame's sample indices split into fixed runs of `chunkSpp`
// ([0, k), [k, 2k), …), each chunk summed from zero by a backend, and the chunks' sums
// added to the frame's in chunk order. The image then depends on the chunk size, the
// seed and the device alone: a render's passes, or the processes among which an MPI job
// shares the chunks (session/dealt_chunks.h), cannot change a bit of it.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>

#include "render/film.h"

namespace vkpt::internal {

// A FrameRenderer that renders through `inner` (which must outlive it) chunk by chunk: a
// pass is cut at chunk boundaries, and at each one the inner frame's sums are added to
// the frame's and cleared. AddSumsTo adds the closed chunks' sums, then the open chunk's.
class ChunkedFrame final : public FrameRenderer {
 public:
  ChunkedFrame(FrameRenderer& inner, uint32_t chunkSpp);

  // Passes must follow each other: `begin` is the samples taken so far.
  void AddSamples(uint32_t begin, uint32_t count, std::span<const uint8_t> active,
                  const std::function<void(double)>& progress) override;
  void AddSumsTo(FrameSums& into) override;
  void Clear() override;
  AovSums RenderAovs(const AovRequest& request) override { return inner_.RenderAovs(request); }
  std::string Engine() const override { return inner_.Engine(); }

 private:
  FrameRenderer& inner_;
  const uint32_t chunkSpp_;
  FrameSums closed_;   // chunks [0, done_ / chunkSpp_)
  uint32_t done_ = 0;  // samples per pixel taken
  bool open_ = false;  // the inner frame holds samples of an unfinished chunk
};

}  // namespace vkpt::internal

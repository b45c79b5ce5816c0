// The samples of a frame rendered in passes on this process's own backend: the first pass
// takes 1 sample per pixel, each next one about a second's work at the last pass's rate
// (at most twice its samples), within the time left. The passes run through a
// ChunkedFrame, so the sums are those of the chunks, whatever the passes.
#pragma once

#include <cstdint>
#include <optional>

#include "render/film.h"
#include "session/chunked_frame.h"
#include "session/sample_source.h"

namespace vkpt::internal {

// What the pass sizing knows of the passes so far.
struct PassPlan {
  uint32_t done = 0;           // samples per pixel so far
  uint32_t lastPass = 0;       // samples of the last pass (0: none yet)
  double secondsPerSpp = 0.0;  // of the last pass
};

// How many samples per pixel the next pass takes: about `passSeconds` of work at the rate
// of the last pass (at most twice its samples), within `secondsLeft` (none: no time
// budget), and never at or past `limit`; 0 when nothing fits.
uint32_t NextPassSpp(const PassPlan& plan, uint32_t limit, std::optional<double> secondsLeft, double passSeconds = 1.0);

class LocalPasses final : public SampleSource {
 public:
  // `frame` is the backend's, and must outlive this.
  LocalPasses(FrameRenderer& frame, uint32_t chunkSpp) : chunked_(frame, chunkSpp) {}

  uint32_t Advance(const SampleRequest& request) override;
  FrameSums Sums() override { return chunked_.Sums(); }
  AovSums RenderAovs(const AovRequest& request) override { return chunked_.RenderAovs(request); }
  std::string Engine() const override { return chunked_.Engine(); }

 private:
  ChunkedFrame chunked_;
  PassPlan plan_;
};

}  // namespace vkpt::internal

#include "session/chunked_frame.h"

#include <algorithm>

#include "util/error.h"

namespace vkpt::internal {

ChunkedFrame::ChunkedFrame(FrameRenderer& inner, uint32_t chunkSpp) : inner_(inner), chunkSpp_(chunkSpp) {
  if (chunkSpp_ == 0) throw Error("a chunk needs at least one sample per pixel");
}

void ChunkedFrame::AddSamples(uint32_t begin, uint32_t count, std::span<const uint8_t> active,
                              const std::function<void(double)>& progress) {
  if (begin != done_) throw Error("a chunked frame's passes must follow each other");
  uint32_t added = 0;
  while (added < count) {
    const uint32_t first = begin + added;
    const uint32_t piece = std::min(count - added, chunkSpp_ - first % chunkSpp_);
    std::function<void(double)> pieceProgress;
    if (progress) pieceProgress = [&progress, added, piece, count](double f) { progress((added + f * piece) / count); };
    inner_.AddSamples(first, piece, active, pieceProgress);
    open_ = true;
    added += piece;
    if ((first + piece) % chunkSpp_ == 0) {
      inner_.AddSumsTo(closed_);
      inner_.Clear();
      open_ = false;
    }
  }
  done_ += count;
}

void ChunkedFrame::AddSumsTo(FrameSums& into) {
  if (closed_.pixels.empty()) {
    inner_.AddSumsTo(into);
    return;
  }
  AddChunk(into, closed_);
  if (open_) inner_.AddSumsTo(into);
}

void ChunkedFrame::Clear() {
  closed_ = FrameSums{};
  inner_.Clear();
  done_ = 0;
  open_ = false;
}

}  // namespace vkpt::internal

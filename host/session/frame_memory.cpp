#include "session/frame_memory.h"

#include <algorithm>

#include <glm/glm.hpp>

#include "render/denoise.h"
#include "render/film.h"
#include "shared/layout.h"

namespace vkpt::internal {
namespace {

constexpr uint64_t kSums = sizeof(PixelSums);
constexpr uint64_t kImage = 2 * sizeof(glm::vec3);  // an Image: the mean and its variance
constexpr uint64_t kVec4 = sizeof(glm::vec4);

// A render's sums: the backend's (the open chunk), the closed chunks' (ChunkedFrame) and
// the session's copy for decisions, checkpoints and the result (render_session.cpp).
uint64_t SumsBytes(const FrameShape& s) {
  uint64_t bytes = 3 * kSums;
  if (s.gpu) {
    // The device sums in float: accumulation (2 vec4) and counters (1 uvec4), read back
    // into host-visible copies of both; the active mask as uint per pixel.
    const uint64_t device = 2 * kVec4 + sizeof(glm::uvec4);
    bytes = 2 * kSums + device + sizeof(uint32_t) + (s.deviceInHost ? device : 0);
  }
  // Rank 0 of an MPI job: a chunk from each other rank may wait, decoded, with its message.
  if (s.ranks > 1) bytes += uint64_t(s.ranks - 1) * 2 * kSums;
  if (s.compare) bytes += 3 * kSums + kImage;  // the CPU reference frame and its image
  return bytes;
}

// The AOV pass's sums, kept to the end (RenderedFrame::aovs).
uint64_t AovSumsBytes(const FrameShape& s) { return s.aovPass ? sizeof(AovPixelSums) : 0; }

// The GPU's AOV sums, and triangles for the ids, while the pass runs: on the device and
// read back.
uint64_t AovPassBytes(const FrameShape& s) {
  if (!s.aovPass || !s.gpu) return 0;
  return (shader::kAovSumsPerPixel * kVec4 + (s.aovIds ? sizeof(uint32_t) : 0)) * (s.deviceInHost ? 2 : 1);
}

// While the denoiser runs: DenoiseInput (colour, guide, albedo) and the two images the
// iterations alternate between (the GPU: four device buffers, a readback and the result).
uint64_t DenoiserBytes(const FrameShape& s) {
  if (!s.denoise) return 0;
  const uint64_t input = sizeof(DenoiseInput::color[0]) * 3;
  return input + (s.gpu ? (s.deviceInHost ? 4 * kVec4 : 0) + 2 * kVec4 : 2 * kVec4);
}

// While the files are written: the AOV layers, and the largest file while it is encoded.
// An EXR holds the image and its layers: per channel a float plane, tinyexr's encoding
// and vkpt's copy of it. PNG and PFM hold one image (or AOV) per file: 8-bit RGB or float
// RGB, and the encoded bytes at most that size twice (stb's filtered rows, then the file).
uint64_t WriteBytes(const FrameShape& s) {
  const uint64_t layers = sizeof(float) * s.aovChannels;
  if (s.exrOutput) return layers + 3 * sizeof(float) * (3 + s.aovChannels);
  return layers + 3 * sizeof(glm::vec3);
}

}  // namespace

std::vector<MemoryPart> FrameMemoryParts(const FrameShape& s) {
  // What lives to the end of the frame, then the largest of the steps after the render,
  // which follow one another: the AOV pass, the denoiser, the files.
  const uint64_t aovPass = AovPassBytes(s), denoiser = DenoiserBytes(s), write = WriteBytes(s);
  const uint64_t step = std::max({aovPass, denoiser, write});
  std::vector<MemoryPart> parts = {
      {"sums", SumsBytes(s)},
      {"image", kImage + sizeof(uint8_t)},  // and the adaptive sampler's active mask
      {"AOV sums", AovSumsBytes(s)},
      {"denoised image", s.denoise ? kImage : 0},
      {step == write      ? "writing"
       : step == denoiser ? "denoising"
                          : "AOV pass",
       step},
  };
  std::erase_if(parts, [](const MemoryPart& p) { return p.bytesPerPixel == 0; });
  return parts;
}

uint64_t BytesPerPixel(const std::vector<MemoryPart>& parts) {
  uint64_t total = 0;
  for (const MemoryPart& p : parts) total += p.bytesPerPixel;
  return total;
}

std::string DescribeParts(const std::vector<MemoryPart>& parts) {
  std::string text;
  for (const MemoryPart& p : parts) text += (text.empty() ? "" : ", ") + p.name + " " + std::to_string(p.bytesPerPixel);
  return text + " bytes a pixel";
}

}  // namespace vkpt::internal

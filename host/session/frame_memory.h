// The host memory a render of one frame needs beside the scene, per pixel and by part:
// counted against --max-memory before any of it is allocated (engine/loaded_scene.cpp), like
// every part of the scene. Each part is what the code holds at once, from the sizes of
// the structures that hold it, so the count follows the code; a test compares it with the
// peak a render measures (tests/test_frame_memory.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vkpt::internal {

// What decides a frame's memory.
struct FrameShape {
  uint32_t width = 0, height = 0;
  bool gpu = false;          // a Vulkan device renders
  bool deviceInHost = true;  // its device memory is host memory (lavapipe, an integrated GPU)
  bool compare = false;      // --compare: a CPU reference frame as well
  uint32_t ranks = 1;        // an MPI job's ranks (rank 0 holds the chunks in flight)
  bool aovPass = false;      // an AOV pass (some AOV needs it, or --denoise)
  bool aovIds = false;       // the AOV pass finds each pixel's triangle (an id AOV)
  uint32_t aovChannels = 0;  // float channels of the AOV layers written
  bool denoise = false;      // --denoise (the raw image is written as well)
  bool exrOutput = false;    // --out is an EXR: the image and its AOV layers in one file
};

struct MemoryPart {
  std::string name;  // "sums", "image", …
  uint64_t bytesPerPixel = 0;
};

// The parts of a frame of this shape; parts of 0 bytes are left out.
std::vector<MemoryPart> FrameMemoryParts(const FrameShape& shape);

// Bytes per pixel of all the parts.
uint64_t BytesPerPixel(const std::vector<MemoryPart>& parts);

// "sums 168, image 25, output 24 bytes a pixel"
std::string DescribeParts(const std::vector<MemoryPart>& parts);

}  // namespace vkpt::internal

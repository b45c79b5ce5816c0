// What the library's tests (test_api*.cpp) share: the Cornell box, and a small render of it.
#pragma once

#include <cstdint>
#include <string>

#include "test_util.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal::test {

inline std::string Cornell() { return SourcePath("scenes/cornell.gltf"); }

// 24 × 16 pixels, one chunk of 4 samples per pixel.
inline vkpt::RenderOptions SmallRender(uint32_t seed = 0) {
  vkpt::RenderOptions o;
  o.width = 24;
  o.height = 16;
  o.spp = o.chunkSpp = 4;
  o.seed = seed;
  return o;
}

}  // namespace vkpt::internal::test

// What loading a glTF may do: how much memory it may plan for and which files it may
// read. A glTF is untrusted input; these are the limits that make it safe to open.
#pragma once

#include <cstdint>
#include <string>

namespace vkpt::internal {

struct LoadLimits {
  // Host memory the scene may need, from its files to the renderer's arrays; 0 selects
  // DefaultMaxMemory(). Checked before anything large is read or allocated.
  uint64_t maxMemory = 0;
  // Texels of level 0 of all the images the materials use (--max-texels); 0 selects
  // kDefaultMaxTextureTexels. Checked from the images' headers, before any is decoded.
  uint64_t maxTextureTexels = 0;
  // Lifts the confinement of buffer and image URIs to the scene file's folder.
  bool allowExternalUris = false;
};

// 2^28 texels: 1 GiB of RGBA8, and with every mip level still within one texel buffer of
// lavapipe's (2^27 RGBA32UI texels of four RGBA8 texels each).
constexpr uint64_t kDefaultMaxTextureTexels = uint64_t(1) << 28;

// Half of the memory this process may have: physical RAM, or a smaller cgroup limit or
// address-space limit (ulimit -v).
// Half, because the renderer's own arrays (image sums, device copies) come on top of
// what the scene is charged for.
uint64_t DefaultMaxMemory();

// The running total of what a scene will need, checked against the limit as each part
// is counted, before that part is read or allocated.
class MemoryBudget {
 public:
  MemoryBudget(uint64_t limit, std::string file) : limit_(limit), file_(std::move(file)) {}

  // Adds `bytes` for `what` ("accessors[3] (268435455 × VEC3)"); throws Error
  // naming the file, `what`, the figure, the limit and `advice` when the total passes the
  // limit.
  void Charge(uint64_t bytes, const std::string& what,
              const std::string& advice = "raise --max-memory if the scene is genuine");

  uint64_t Used() const { return used_; }
  uint64_t Limit() const { return limit_; }

 private:
  uint64_t limit_;
  uint64_t used_ = 0;
  std::string file_;
};

}  // namespace vkpt::internal

// Wall-clock seconds of each phase of a run, and the timer that takes them.
#pragma once

#include <chrono>

namespace vkpt::internal {

struct RunTimes {
  double load = 0.0;         // reading and checking the glTF
  double environment = 0.0;  // reading the --env map and building its distribution
  double pose = 0.0;         // posing the scene: animation, skins, morph targets, world-space triangles
  double prepare = 0.0;      // BVH build and the renderers' arrays (includes bvh.build_ms)
  double upload = 0.0;       // Vulkan: the scene into device memory and the kernels (0 on the CPU)
  double render = 0.0;       // the render itself (--compare: the Vulkan one)
  double aov = 0.0;          // the AOV pass (0 without --aov)
  double denoise = 0.0;      // --denoise: the filter (0 without)
  double write = 0.0;        // encoding and writing --out
  double total = 0.0;        // from start to the stats being written
};

inline double SecondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Times the phases of a run one after another: each Lap is the time since the last.
class PhaseTimer {
 public:
  void Lap(double& seconds) {
    seconds = SecondsSince(last_);
    Restart();
  }
  void Restart() { last_ = std::chrono::steady_clock::now(); }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace vkpt::internal

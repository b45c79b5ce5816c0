// vkpt-bench's command line (its options and their checks), and the clock it times with.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include "bvh/bvh.h"

namespace vkpt::internal::bench {

using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point t0);  // since t0

struct Options {
  std::string scene;
  uint32_t procedural = 0;
  uint32_t width = 1024, height = 1024;
  unsigned threads = 0;  // 0: all cores
  bool json = false;
  bool markdown = false;          // one row of bench/README.md's table
  std::string quality;            // --quality REF.pfm: time to reach relMSE <= target
  double target = 1.2e-3;         // --target X: the relMSE --quality waits for
  std::string writeGlb;           // --write-glb FILE: the procedural scene as a glTF, no benchmark
  std::string splits = "object";  // --splits: the builder as compared with Embree's
  uint32_t leafSize = BvhBuildOptions{}.maxLeafSize;
  float traversalCost = BvhBuildOptions{}.traversalCost;  // SAH cost of a node visit
};

constexpr int kBuildRuns = 3;
constexpr int kTraceRuns = 3;  // ray timings: the fastest of three

// The options of argv; prints the usage and exits 2 on anything malformed.
Options Parse(int argc, char** argv);

// The BVH the options ask for, built on `threads` threads.
BvhBuildOptions BuildOptions(const Options& o, unsigned threads);

}  // namespace vkpt::internal::bench

#include "bench_options.h"

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace vkpt::internal::bench {
namespace {

[[noreturn]] void Usage(const std::string& why) {
  std::fprintf(stderr,
               "vkpt-bench: %s\nusage: vkpt-bench (--scene FILE | --procedural N) [--width W] [--height H] "
               "[--threads N] [--splits object|spatial|auto] [--leaf-size N] [--traversal-cost C] [--json | "
               "--markdown] [--quality REF.pfm [--target RELMSE]] [--write-glb FILE]\n",
               why.c_str());
  std::exit(2);
}

uint32_t Number(const char* opt, const char* text) {
  uint32_t v = 0;
  auto [end, ec] = std::from_chars(text, text + std::strlen(text), v);
  if (ec != std::errc() || *end || v == 0) Usage(std::string(opt) + " expects a positive number, got \"" + text + "\"");
  return v;
}

}  // namespace

double Seconds(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

Options Parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) Usage(a + " needs a value");
      return argv[++i];
    };
    if (a == "--scene") o.scene = value();
    else if (a == "--procedural") o.procedural = Number("--procedural", value());
    else if (a == "--width") o.width = Number("--width", value());
    else if (a == "--height") o.height = Number("--height", value());
    else if (a == "--threads") o.threads = Number("--threads", value());
    else if (a == "--json") o.json = true;
    else if (a == "--markdown") o.markdown = true;
    else if (a == "--quality") o.quality = value();
    else if (a == "--target") {
      const char* v = value();
      char* end = nullptr;
      o.target = std::strtod(v, &end);
      if (*end || !(o.target > 0.0 && o.target < 1.0))
        Usage(std::string("--target expects a relMSE in (0, 1), got \"") + v + "\"");
    } else if (a == "--write-glb") o.writeGlb = value();
    else if (a == "--splits") {
      o.splits = value();
      if (!ParseSplitMode(o.splits)) Usage("--splits must be object, spatial or auto, got \"" + o.splits + "\"");
    } else if (a == "--leaf-size") o.leafSize = Number("--leaf-size", value());
    else if (a == "--traversal-cost") {
      const char* v = value();
      char* end = nullptr;
      o.traversalCost = std::strtof(v, &end);
      if (*end || !(o.traversalCost > 0.0f))
        Usage(std::string("--traversal-cost expects a positive number, got \"") + v + "\"");
    } else if (a == "-h" || a == "--help") Usage("benchmarks BVH build, traversal and path tracing");
    else Usage("unknown option \"" + a + "\"");
  }
  if (o.scene.empty() == (o.procedural == 0)) Usage("give exactly one of --scene FILE and --procedural N");
  if (o.quality.empty() && o.target != Options{}.target) Usage("--target is the relMSE --quality waits for");
  if (!o.quality.empty() && o.markdown) Usage("--quality prints text or --json, not --markdown");
  if (!o.writeGlb.empty() && o.procedural == 0) Usage("--write-glb writes the --procedural scene");
  return o;
}

BvhBuildOptions BuildOptions(const Options& o, unsigned threads) {
  BvhBuildOptions b;
  b.threads = threads;
  b.splits = *ParseSplitMode(o.splits);
  b.maxLeafSize = o.leafSize;
  b.traversalCost = o.traversalCost;
  return b;
}

}  // namespace vkpt::internal::bench

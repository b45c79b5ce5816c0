#include "app/run.h"

#include <signal.h>

#include <cstdio>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "app/prepare.h"
#include "app/render_frame.h"
#include "app/report.h"
#include "app/run_stats.h"
#include "app/sequence.h"
#include "cluster/agreement.h"
#include "cluster/chunk_dealer.h"
#include "image/image.h"
#include "image/image_compare.h"
#include "session/aov.h"
#include "session/backend.h"
#include "session/dealt_chunks.h"
#include "session/local_passes.h"
#include "session/render_session.h"
#include "util/atomic_write.h"
#include "util/content_hash.h"
#include "util/error.h"
#include "util/graceful_stop.h"
#include "vk/context.h"

namespace vkpt::internal {
namespace {

int ListDevices() {
  std::vector<vk::DeviceInfo> devices = vk::ListDevices();
  if (devices.empty()) {
    std::printf("no Vulkan devices (install mesa-vulkan-drivers for lavapipe, a software device)\n");
    return 0;
  }
  for (const vk::DeviceInfo& d : devices)
    std::printf("%u: %s (%s, Vulkan %u.%u)%s\n", d.index, d.name.c_str(), d.TypeName(),
                VK_API_VERSION_MAJOR(d.apiVersion), VK_API_VERSION_MINOR(d.apiVersion),
                d.hasComputeQueue ? "" : " [no compute queue]");
  return 0;
}

// --diff A B: two existing images, no rendering.
int Diff(const Options& o) {
  Image a = ReadPfm(o.diff[0]);
  Image b = ReadPfm(o.diff[1]);
  if (!o.outGiven.empty()) CheckOutputPath(o.outGiven);
  ImageComparison c = CompareImages(a, b);
  std::printf("vkpt: %s (A) vs %s (B)\n%s\n", o.diff[0].c_str(), o.diff[1].c_str(), c.Summary().c_str());
  if (!o.outGiven.empty()) WriteImage(DifferenceHeatmap(a, b), o.outGiven);
  return c.statisticallyAgree ? 0 : 4;
}

// Runs `step` and returns its exit status (0, or 1 and the error's message).
int Attempt(const std::function<void()>& step, std::string* message) {
  try {
    step();
    return 0;
  } catch (const Error& e) {
    *message = e.what();
  } catch (const std::bad_alloc&) {
    *message = "out of memory";
  } catch (const std::exception& e) {
    *message = e.what();
  }
  return 1;
}

// The options that must be the same on every rank: all but where and how each renders.
uint64_t FrameKey(const Options& o, Prepared& p) {
  Options shared = o;
  shared.backend = Backend::Auto;
  shared.device.clear();
  shared.threads = 0;
  shared.batch = 0;
  shared.validation = shared.verbose = false;
  const std::string key = OptionsAsJson(shared) + std::to_string(p.scene().contentHash);
  ContentHash hash;
  hash.Add({reinterpret_cast<const unsigned char*>(key.data()), key.size()});
  return hash.Value();
}

// The options on every rank, refused where a run needs one process.
int ParseOnEveryRank(Cluster& cluster, int argc, char** argv, Options& o) {
  std::string message;
  int status = 0;
  try {
    o = ParseOptions(argc, argv);
    if (o.compare) throw UsageError("--compare renders in one process; run it without mpirun");
    if (!o.diff.empty() || o.listDevices || o.help || o.version)
      throw UsageError("--diff, --list-devices, --help and --version run in one process; run them without mpirun");
  } catch (const UsageError& e) {
    status = 2;
    message = e.what();
  }
  return AgreeOnOutcome(cluster, status, message, "usage error");
}

// Frame `i` of a sequence after the first: posed and built again from the loaded file.
void NextFrame(Prepared& p, const Options& f, uint32_t ranks) {
  p.start = std::chrono::steady_clock::now();
  p.times() = RunTimes{};  // the file was read once, for the first frame
  PrepareFrame(p, f, false, ranks);
}

void PrintFrameLine(uint32_t number, size_t i, size_t frames, const Options& f, Prepared& p, double seconds) {
  std::printf("vkpt: frame %u (%zu of %zu, %.6g s): pose %.3f s, BVH and arrays %.3f s, upload %.3f s, render %.3f s\n",
              number, i + 1, frames, f.at.value_or(0.0), p.times().pose, p.times().prepare, p.times().upload, seconds);
  std::fflush(stdout);
}

// Where a frame of a sequence puts its stats: a new entry of `stats` with --stats, else
// nowhere (a sequence without --stats keeps nothing per frame).
std::string* FrameStats(const Options& o, std::vector<std::string>& stats) {
  return o.stats.empty() ? nullptr : &stats.emplace_back();
}

void PrintSequenceEnd(const Options& o, size_t done, size_t frames, std::chrono::steady_clock::time_point start,
                      const std::vector<std::string>& stats) {
  std::printf("vkpt: %zu of %zu frames in %.3f s\n", done, frames, SecondsSince(start));
  if (!o.stats.empty()) WriteSequenceStats(o.stats, stats);
}

// Rank 0 deals the frame's chunks to every rank (itself included), then writes it; the
// others render the chunks dealt to them. Returns the exit status, the same on every rank.
int RenderDealt(Cluster& cluster, const Options& o, Prepared& p, std::string* frameStats = nullptr) {
  const ChunkPlan plan{o.spp, o.chunkSpp};
  FrameRenderer& renderer = *p.view.renderer;
  int status = 0;
  if (cluster.Rank() != 0) {
    RenderDealtChunks(cluster, ChunkRendererOf(renderer, plan));
  } else {
    DealtChunks source(cluster, renderer, plan);
    status = Finish(o, p, p.client->Finish(p.view, source, p.settings), nullptr, frameStats);
  }
  return cluster.MaxOf(status);
}

}  // namespace

// --frames: each frame posed, built, rendered and written in turn from one load; the
// first signal ends the sequence after the frame it stops.
int RunSequence(const Options& o) {
  const std::vector<uint32_t> numbers = FrameNumbers(*o.frames);
  for (uint32_t k : numbers) CheckOutputPath(FramePath(o.out, k));
  Prepared p = Prepare(FrameOptions(o, numbers.front()), true);
  const auto start = p.start;
  GracefulStop stop;
  std::vector<std::string> stats;  // with --stats, each frame's (about 2 KB)
  int status = 0;
  size_t i = 0;  // frames rendered
  for (; i < numbers.size() && status == 0; ++i) {
    const Options f = FrameOptions(o, numbers[i]);
    if (i > 0) NextFrame(p, f, 1);
    LocalPasses source(*p.view.renderer, o.chunkSpp);
    const RenderedView rendered = p.client->Finish(p.view, source, p.settings);
    status = Finish(f, p, rendered, nullptr, FrameStats(o, stats));
    PrintFrameLine(numbers[i], i, numbers.size(), f, p, rendered.frame.seconds);
  }
  PrintSequenceEnd(o, i, numbers.size(), start, stats);
  return status;
}

int Run(const Options& o) {
  if (o.listDevices) return ListDevices();
  if (!o.diff.empty()) return Diff(o);
  if (o.frames) return RunSequence(o);
  Prepared p = Prepare(o, true);
  std::optional<RenderedFrame> reference;
  if (o.compare) reference = RenderReference(p, o);
  LocalPasses source(*p.view.renderer, o.chunkSpp);
  // From here the first SIGINT/SIGTERM stops the render after its pass, and the image of
  // the samples taken is still written.
  GracefulStop stop;
  const RenderedView rendered = p.client->Finish(p.view, source, p.settings);
  return Finish(o, p, rendered, reference ? &*reference : nullptr);
}

// Under mpirun: every rank loads the file and builds each frame; the frames' chunks are
// dealt among the ranks one frame after another (RenderDealt).
int RunRank(Cluster& cluster, int argc, char** argv) {
  Options o;
  if (const int status = ParseOnEveryRank(cluster, argc, argv, o)) return status;
  const bool root = cluster.Rank() == 0;
  const uint32_t ranks = root ? uint32_t(cluster.Size()) : 1;
  const std::vector<uint32_t> numbers = o.frames ? FrameNumbers(*o.frames) : std::vector<uint32_t>{0};
  Prepared p;
  std::vector<std::string> stats;    // with --stats, each frame's
  std::optional<GracefulStop> stop;  // rank 0 stops dealing at a signal; the others finish their chunk
  std::chrono::steady_clock::time_point start;
  int status = 0;
  size_t i = 0;  // frames rendered
  for (; i < numbers.size() && status == 0; ++i) {
    const Options f = o.frames ? FrameOptions(o, numbers[i]) : o;
    std::string message;
    status = Attempt(
        [&] {
          if (i == 0 && o.frames && root)
            for (uint32_t k : numbers) CheckOutputPath(FramePath(o.out, k));
          if (i == 0) p = Prepare(f, root, ranks);
          else NextFrame(p, f, ranks);
        },
        &message);
    if ((status = AgreeOnOutcome(cluster, status, message, "error"))) return status;
    if (i == 0) {
      start = p.start;
      stop.emplace();
      if (!cluster.AllEqual(FrameKey(o, p))) {
        if (root)
          PrintError("usage error",
                     "the ranks were given different frames: only --backend, --device, --threads, --batch, "
                     "--validation and -v may differ between ranks");
        return 2;
      }
    }
    if (!o.frames) return RenderDealt(cluster, o, p);
    status = RenderDealt(cluster, f, p, root ? FrameStats(o, stats) : nullptr);
    if (root) PrintFrameLine(numbers[i], i, numbers.size(), f, p, p.times().render);
  }
  if (root) PrintSequenceEnd(o, i, numbers.size(), start, stats);
  return status;
}

}  // namespace vkpt::internal

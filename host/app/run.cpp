#include "app/run.h"

#include <signal.h>

#include <cstdio>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "app/interactive.h"
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
#include "session/dealt_chunks.h"
#include "session/local_passes.h"
#include "session/render_session.h"
#include "util/atomic_write.h"
#include "util/content_hash.h"
#include "util/error.h"
#include "util/graceful_stop.h"

namespace vkpt::internal {
namespace {

int ListDevices() {
  const std::vector<vkpt::Device> devices = vkpt::Devices();
  if (devices.empty()) {
    std::printf("no Vulkan devices (install mesa-vulkan-drivers for lavapipe, a software device)\n");
    return 0;
  }
  for (const vkpt::Device& d : devices)
    std::printf("%u: %s (%s, Vulkan %u.%u)%s\n", d.index, d.name.c_str(), d.type.c_str(), d.apiMajor, d.apiMinor,
                d.compute ? "" : " [no compute queue]");
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
  shared.api.scene.backend = vkpt::Backend::Auto;
  shared.api.scene.device.clear();
  shared.api.scene.threads = 0;
  shared.api.render.batch = 0;
  shared.api.scene.validation = shared.verbose = false;
  const std::string key = OptionsAsJson(shared) + std::to_string(p.scene().Stats().contentHash);
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
    if (!o.diff.empty() || o.listDevices || o.interactive || o.help || o.version)
      throw UsageError(
          "--diff, --list-devices, --interactive, --help and --version run in one process; run them without mpirun");
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
              number, i + 1, frames, f.api.render.time.value_or(0.0), p.times().pose, p.times().prepare,
              p.times().upload, seconds);
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

// How a run's frames are prepared and rendered: in this process (LocalFrames), or dealt
// among an MPI job's ranks (DealtFrames). RunFrames is the one loop over frames for both;
// a single image is a sequence of one frame.
class FrameWay {
 public:
  virtual ~FrameWay() = default;
  // Frame `i` (options `f`) prepared in `p`: loaded at the first, posed and built again
  // after. Returns 0, or the exit status that ends the run.
  virtual int Prepare(Prepared& p, const Options& o, const Options& f, size_t i) = 0;
  // The frame rendered and written; its exit status, and its rendering time in `seconds`.
  virtual int Render(const Options& f, Prepared& p, std::string* frameStats, double& seconds) = 0;
  virtual bool Reports() const { return true; }  // this process prints and writes the run's results
};

// The output files of a sequence checked before the first frame is rendered: the first
// frame's and the last's, which share the folder, and whose number is the widest. (Every
// frame's would cost a million stat calls, 8 s, before a million-frame run's first frame.)
void CheckFramePaths(const Options& o) {
  if (!o.frames) return;
  CheckOutputPath(FramePath(o.out, o.frames->first));
  CheckOutputPath(FramePath(o.out, FrameNumber(*o.frames, FrameCount(*o.frames) - 1)));
}

class LocalFrames : public FrameWay {
 public:
  int Prepare(Prepared& p, const Options& o, const Options& f, size_t i) override {
    if (i == 0) {
      CheckFramePaths(o);
      p = vkpt::internal::Prepare(f, true);
    } else {
      NextFrame(p, f, 1);
    }
    return 0;
  }
  int Render(const Options& f, Prepared& p, std::string* frameStats, double& seconds) override {
    std::optional<RenderedFrame> reference;
    if (f.compare) reference = RenderReference(p, f);
    // From here the first SIGINT/SIGTERM stops the render after its pass (a sequence after
    // that frame), and the image of the samples taken is still written.
    if (!stop_) stop_.emplace();
    LocalPasses source(*p.view.renderer, f.api.render.chunkSpp);
    const RenderedView rendered = p.client->Finish(p.view, source, p.settings);
    seconds = rendered.frame.seconds;
    return Finish(f, p, rendered, reference ? &*reference : nullptr, frameStats);
  }

 private:
  std::optional<GracefulStop> stop_;
};

// Every rank loads the file and builds each frame; rank 0 deals the frame's chunks to
// every rank (itself included) and writes it, the others render the chunks dealt them.
class DealtFrames : public FrameWay {
 public:
  explicit DealtFrames(Cluster& cluster) : cluster_(cluster) {}
  int Prepare(Prepared& p, const Options& o, const Options& f, size_t i) override {
    const uint32_t ranks = Reports() ? uint32_t(cluster_.Size()) : 1;
    std::string message;
    int status = Attempt(
        [&] {
          if (i > 0) {
            NextFrame(p, f, ranks);
          } else {
            if (Reports()) CheckFramePaths(o);
            p = vkpt::internal::Prepare(f, Reports(), ranks);
          }
        },
        &message);
    if ((status = AgreeOnOutcome(cluster_, status, message, "error")) || i > 0) return status;
    if (cluster_.AllEqual(FrameKey(o, p))) return 0;
    if (Reports())
      PrintError("usage error",
                 "the ranks were given different frames: only --backend, --device, --threads, --batch, "
                 "--validation and -v may differ between ranks");
    return 2;
  }
  // A signal makes rank 0 stop dealing; the others finish their chunk.
  int Render(const Options& f, Prepared& p, std::string* frameStats, double& seconds) override {
    if (!stop_) stop_.emplace();
    const ChunkPlan plan{f.Budget().spp, f.api.render.chunkSpp};
    FrameRenderer& renderer = *p.view.renderer;
    int status = 0;
    if (!Reports()) {
      RenderDealtChunks(cluster_, ChunkRendererOf(renderer, plan));
    } else {
      DealtChunks source(cluster_, renderer, plan);
      status = Finish(f, p, p.client->Finish(p.view, source, p.settings), nullptr, frameStats);
    }
    seconds = p.times().render;
    return cluster_.MaxOf(status);
  }
  bool Reports() const override { return cluster_.Rank() == 0; }

 private:
  Cluster& cluster_;
  std::optional<GracefulStop> stop_;
};

// Every frame in turn from one load; the first error or signal ends the run after that
// frame. A sequence prints a line per frame and keeps each frame's stats for --stats.
int RunFrames(const Options& o, FrameWay& way) {
  const FrameRange range = o.frames.value_or(FrameRange{});  // a single image: frame 0 alone
  const uint64_t frames = FrameCount(range);
  const bool sequence = o.frames && way.Reports();
  Prepared p;
  std::chrono::steady_clock::time_point start;  // of the first frame's preparation
  std::vector<std::string> stats;               // with --stats, each frame's (about 2 KB)
  int status = 0;
  uint64_t i = 0;  // frames rendered
  for (; i < frames && status == 0; ++i) {
    const uint32_t number = FrameNumber(range, i);
    const Options f = o.frames ? FrameOptions(o, number) : o;
    if (const int refused = way.Prepare(p, o, f, i)) return refused;
    if (i == 0) start = p.start;
    double seconds = 0.0;
    status = way.Render(f, p, sequence ? FrameStats(o, stats) : nullptr, seconds);
    if (sequence) PrintFrameLine(number, i, frames, f, p, seconds);
  }
  if (sequence) PrintSequenceEnd(o, i, frames, start, stats);
  return status;
}

}  // namespace

int Run(const Options& o) {
  if (o.listDevices) return ListDevices();
  if (!o.diff.empty()) return Diff(o);
  if (o.interactive) return RunInteractive(o);
  LocalFrames local;
  return RunFrames(o, local);
}

int RunRank(Cluster& cluster, int argc, char** argv) {
  Options o;
  if (const int status = ParseOnEveryRank(cluster, argc, argv, o)) return status;
  DealtFrames dealt(cluster);
  return RunFrames(o, dealt);
}

}  // namespace vkpt::internal

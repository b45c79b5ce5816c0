// Distributed rendering over MPI (cluster/, session/dealt_chunks.h, app/run.cpp's RunRank), run through mpirun on
// this machine: the image file is byte-identical for one process and for 2 and 3 ranks,
// on the CPU backend and on lavapipe, for the Cornell box and a textured corpus model,
// also when a slowed rank makes the ranks take unequal chunk counts; a rank failing
// mid-render, or killed by a signal, ends the job non-zero, naming it, and leaves no file;
// setup errors are reported once; ranks given different frames are refused; Ctrl-C on
// mpirun leaves the image of the chunks done; --noise-target and adaptive sampling stop
// where one process
// stops, with the same bytes. Built only when CMake found MPI (VKPT_MPIEXEC).
#include <gtest/gtest.h>

#include <signal.h>

#include <cstdlib>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "test_util.h"

namespace vkpt::internal {
namespace {

using nlohmann::json;
using test::ProcessResult;

const std::string kCornell = test::SourcePath("scenes/cornell.gltf");
const std::string kBoxTextured = test::CorpusPath("valid/BoxTextured/glTF/BoxTextured.gltf");

// Open MPI refuses root without the first two; CI runs as root. In the sanitizer build,
// leaks are not checked in the ranks: Open MPI 4.1.4 keeps allocations past
// MPI_Finalize, in stacks that cannot be unwound (it is built without frame pointers),
// so no suppression can name them. Memory errors are still checked, and vkpt's own code
// is leak-checked by the rest of the suite (test_progressive.cpp for the chunk sums).
std::vector<std::string> MpiEnvironment() {
  std::vector<std::string> env = {"OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1"};
  if (const char* asan = std::getenv("ASAN_OPTIONS"))
    env.push_back(std::string("ASAN_OPTIONS=") + asan + ":detect_leaks=0");
  return env;
}
const std::vector<std::string> kMpiEnv = MpiEnvironment();

// mpirun with one app context per entry of `ranks`: each is the environment of one rank
// ("" for none), all running `build/vkpt args`.
ProcessResult MpiRun(const std::vector<std::string>& ranks, const std::vector<std::string>& args) {
  std::vector<std::string> argv = {"--oversubscribe", "--bind-to", "none"};
  for (size_t r = 0; r < ranks.size(); ++r) {
    std::vector<std::string> context = {"-n", "1"};
    if (r > 0) context.insert(context.begin(), ":");
    if (!ranks[r].empty()) {
      context.push_back("env");
      context.push_back(ranks[r]);
    }
    context.push_back(VKPT_BINARY);
    argv.insert(argv.end(), context.begin(), context.end());
    argv.insert(argv.end(), args.begin(), args.end());
  }
  return test::RunProgram(VKPT_MPIEXEC, argv, 300.0, "", kMpiEnv);
}

// Two ranks: rank 0 renders `args`, rank 1 `args` and `rank1Extra`.
ProcessResult MpiRunTwo(const std::vector<std::string>& args, const std::vector<std::string>& rank1Extra) {
  std::vector<std::string> argv = {"--oversubscribe", "--bind-to", "none", "-n", "1", VKPT_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  const std::vector<std::string> second = {":", "-n", "1", VKPT_BINARY};
  argv.insert(argv.end(), second.begin(), second.end());
  argv.insert(argv.end(), args.begin(), args.end());
  argv.insert(argv.end(), rank1Extra.begin(), rank1Extra.end());
  return test::RunProgram(VKPT_MPIEXEC, argv, 120.0, "", kMpiEnv);
}

ProcessResult MpiRun(int ranks, const std::vector<std::string>& args) {
  return MpiRun(std::vector<std::string>(size_t(ranks)), args);
}

std::vector<std::string> Frame(const std::string& scene, const std::string& backend, const std::string& out,
                               std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"--scene",   scene, "--backend", backend, "--width", "40",
                                   "--height",  "40",  "--spp",     "72",    "--chunk", "16",
                                   "--threads", "1",   "--seed",    "9",     "--out",   out};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

uint32_t ChunksOf(const json& stats, int rank) { return stats["mpi"]["per_rank"][rank]["chunks"]; }

struct Case {
  const char* backend;
  const std::string* scene;
};

class MpiIdentity : public ::testing::TestWithParam<Case> {};

TEST_P(MpiIdentity, SameImageBytesForOneTwoAndThreeRanks) {
  if (GetParam().scene == &kBoxTextured) VKPT_REQUIRE_SHARED_DATA();
  const auto [backend, scene] = GetParam();
#if defined(VKPT_ADDRESS_SANITIZER)
  if (std::string(backend) == "vulkan")
    GTEST_SKIP() << "28-31 s under AddressSanitizer; the cpu variants check the same ranks' code, the plain build "
                    "runs it";
#endif
  const test::TempFolder dir("mpi-identity");
  ProcessResult one = test::RunVkpt(Frame(*scene, backend, dir / "one.pfm"));
  ASSERT_TRUE(one.ExitedWith(0)) << one.Describe();
  const std::string expected = test::ReadFile(dir / "one.pfm");
  for (int n : {2, 3}) {
    const std::string out = dir / ("ranks" + std::to_string(n) + ".pfm");
    const std::string statsPath = dir / ("ranks" + std::to_string(n) + ".json");
    ProcessResult r = MpiRun(n, Frame(*scene, backend, out, {"--stats", statsPath}));
    ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
    EXPECT_TRUE(test::ReadFile(out) == expected) << n << " ranks gave other bytes than one process";
    const json stats = json::parse(test::ReadFile(statsPath));
    ASSERT_EQ(stats["mpi"]["ranks"], n);
    uint32_t chunks = 0;
    for (int k = 0; k < n; ++k) chunks += ChunksOf(stats, k);
    EXPECT_EQ(chunks, 5u);  // 72 spp in chunks of 16
    EXPECT_EQ(stats["spp"], 72);
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, MpiIdentity,
                         ::testing::Values(Case{"cpu", &kCornell}, Case{"vulkan", &kCornell},
                                           Case{"cpu", &kBoxTextured}, Case{"vulkan", &kBoxTextured}),
                         [](const auto& info) {
                           return std::string(info.param.backend) +
                                  (info.param.scene == &kCornell ? "Cornell" : "BoxTextured");
                         });

// Rank 1 takes 400 ms longer per chunk: rank 0 takes more of the 9 chunks, and the image
// is still the one process's.
TEST(Mpi, DynamicBalancingKeepsTheImage) {
  const test::TempFolder dir("mpi-balance");
  const std::vector<std::string> extra = {"--spp", "144", "--stats", dir / "slow.json"};
  ProcessResult r = MpiRun({"", "VKPT_TEST_CHUNK_DELAY_MS=400"}, Frame(kCornell, "cpu", dir / "slow.pfm", extra));
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  const json stats = json::parse(test::ReadFile(dir / "slow.json"));
  EXPECT_GT(ChunksOf(stats, 0), ChunksOf(stats, 1) + 2) << stats["mpi"].dump();
  EXPECT_EQ(ChunksOf(stats, 0) + ChunksOf(stats, 1), 9u);
  ProcessResult one = test::RunVkpt(Frame(kCornell, "cpu", dir / "one.pfm", {"--spp", "144"}));
  ASSERT_TRUE(one.ExitedWith(0)) << one.Describe();
  EXPECT_TRUE(test::ReadFile(dir / "slow.pfm") == test::ReadFile(dir / "one.pfm"));
}

// --noise-target (with adaptive sampling, its default) across ranks: rank 0 makes the
// decisions of one process at the same chunk boundaries, from the same sums, so the job
// stops at the same sample count with the same pixels active and the same bytes — also
// when a slowed rank makes the ranks take unequal chunk counts.
TEST(Mpi, NoiseTargetAndAdaptiveSamplingKeepTheImage) {
  VKPT_SKIP_UNDER_ADDRESS_SANITIZER("a 1,000-spp adaptive render on both backends, 29 s");
  const test::TempFolder dir("mpi-adaptive");
  for (const char* backend : {"cpu", "vulkan"}) {
    const std::vector<std::string> budget = {"--spp", "1000", "--noise-target", "0.005"};
    auto frame = [&](const std::string& name) {
      std::vector<std::string> extra = budget;
      extra.insert(extra.end(), {"--stats", dir / (name + ".json")});
      return Frame(kCornell, backend, dir / (name + ".pfm"), extra);
    };
    ProcessResult one = test::RunVkpt(frame("one"));
    ASSERT_TRUE(one.ExitedWith(0)) << one.Describe();
    const json expected = json::parse(test::ReadFile(dir / "one.json"));
    ASSERT_EQ(expected["stopped_by"], "noise_target");
    ASSERT_LT(uint64_t(expected["active_pixels"]), 1600u) << "the test needs pixels that stopped early";
    for (const std::vector<std::string>& ranks :
         {std::vector<std::string>{"", ""}, std::vector<std::string>{"", "", "VKPT_TEST_CHUNK_DELAY_MS=150"}}) {
      const std::string name = "ranks" + std::to_string(ranks.size());
      ProcessResult r = MpiRun(ranks, frame(name));
      ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
      EXPECT_TRUE(test::ReadFile(dir / (name + ".pfm")) == test::ReadFile(dir / "one.pfm"))
          << backend << ", " << ranks.size() << " ranks gave other bytes than one process";
      const json stats = json::parse(test::ReadFile(dir / (name + ".json")));
      for (const char* key : {"stopped_by", "spp", "samples", "active_pixels", "estimated_rel_mse"})
        EXPECT_EQ(stats[key], expected[key]) << backend << ", " << ranks.size() << " ranks: " << key;
    }
    std::printf("%s: %s at %d spp, %d samples, %d of 1600 pixels active, for 1, 2 and 3 ranks\n", backend,
                std::string(expected["stopped_by"]).c_str(), int(expected["spp"]), int(expected["samples"]),
                int(expected["active_pixels"]));
  }
}

// Ctrl-C on mpirun: rank 0 stops dealing, takes the chunks in flight and writes the image
// of the chunks added, which is the one-process --spp render of that count, bit for bit.
TEST(Mpi, InterruptWritesTheImageOfTheChunksDone) {
  const test::TempFolder dir("mpi-signal");
  std::vector<std::string> argv = {"--oversubscribe", "--bind-to", "none", "-n", "2", VKPT_BINARY};
  const std::vector<std::string> args =
      Frame(kCornell, "cpu", dir / "stopped.pfm", {"--spp", "100000", "--stats", dir / "stopped.json"});
  argv.insert(argv.end(), args.begin(), args.end());
  ProcessResult r = test::RunProgram(VKPT_MPIEXEC, argv, 120.0, "", kMpiEnv, {},
                                     {.after = "", .signals = {SIGINT}, .delaySeconds = 2.0});
  ASSERT_FALSE(r.timedOut) << r.Describe();
  const json stats = json::parse(test::ReadFile(dir / "stopped.json"));
  EXPECT_EQ(stats["stopped_by"], "signal");
  const uint32_t spp = stats["spp"];
  ASSERT_GT(spp, 0u);
  EXPECT_EQ(spp % 16, 0u) << "a prefix of whole chunks";
  ProcessResult one = test::RunVkpt(Frame(kCornell, "cpu", dir / "one.pfm", {"--spp", std::to_string(spp)}));
  ASSERT_TRUE(one.ExitedWith(0)) << one.Describe();
  EXPECT_TRUE(test::ReadFile(dir / "stopped.pfm") == test::ReadFile(dir / "one.pfm"));
}

TEST(Mpi, FailingRankEndsTheJobWithoutAnImage) {
  const test::TempFolder dir("mpi-fail");
  ProcessResult r = MpiRun({"", "VKPT_TEST_FAIL_AFTER_CHUNKS=1"},
                           Frame(kCornell, "cpu", dir / "fail.png", {"--spp", "400", "--stats", dir / "fail.json"}));
  EXPECT_FALSE(r.ExitedWith(0)) << r.Describe();
  EXPECT_NE(r.err.find("vkpt: error: rank 1 ("), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("VKPT_TEST_FAIL_AFTER_CHUNKS"), std::string::npos) << r.err;
  EXPECT_TRUE(dir.Listing().empty()) << "left: " << testing::PrintToString(dir.Listing());
}

// A rank killed by a signal mid-render (rank 1's shell schedules SIGKILL to itself in 2 s,
// then becomes vkpt for a render far longer): mpirun exits non-zero, naming the rank, and
// no image is written.
TEST(Mpi, KilledRankEndsTheJobWithoutAnImage) {
  const test::TempFolder dir("mpi-killed");
  const std::vector<std::string> args = Frame(kCornell, "cpu", dir / "killed.png", {"--spp", "1000000"});
  std::vector<std::string> command = {VKPT_BINARY};
  command.insert(command.end(), args.begin(), args.end());
  std::string rank1 = "(sleep 2; kill -KILL $$) & exec";
  for (const std::string& a : command) {
    rank1 += " '";
    rank1 += a;
    rank1 += "'";
  }
  std::vector<std::string> argv = {"--oversubscribe", "--bind-to", "none", "-n", "1", VKPT_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  argv.insert(argv.end(), {":", "-n", "1", "sh", "-c", rank1});
  ProcessResult r = test::RunProgram(VKPT_MPIEXEC, argv, 120.0, "", kMpiEnv);
  EXPECT_FALSE(r.timedOut) << r.Describe();
  EXPECT_FALSE(r.ExitedWith(0)) << r.Describe();
  const size_t at = r.err.find("rank 1");
  ASSERT_NE(at, std::string::npos) << r.err;
  const size_t begin = r.err.rfind('\n', at) + 1;
  std::printf("mpirun exited %d after %.1f s: %s\n", r.exitCode, r.seconds,
              r.err.substr(begin, r.err.find('\n', at) - begin).c_str());
  EXPECT_TRUE(dir.Listing().empty()) << "left: " << testing::PrintToString(dir.Listing());
}

// --frames under mpirun: each frame's chunks dealt among the ranks, one frame after
// another, gives the files of one process's sequence, byte for byte; the stats list the
// frames.
TEST(Mpi, FrameSequenceMatchesOneProcess) {
  const test::TempFolder dir("mpi-sequence");
  const std::vector<std::string> extra = {"--frames", "0:2", "--orbit", "20", "--stats", dir / "stats.json"};
  ProcessResult r = MpiRun(2, Frame(kCornell, "cpu", dir / "two.#.pfm", extra));
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_NE(r.out.find("vkpt: 3 of 3 frames"), std::string::npos) << r.out;
  const json stats = json::parse(test::ReadFile(dir / "stats.json"));
  ASSERT_EQ(stats["frames"].size(), 3u);
  EXPECT_EQ(stats["frames"][2]["mpi"]["ranks"], 2);
  ProcessResult one = test::RunVkpt(Frame(kCornell, "cpu", dir / "one.#.pfm", {"--frames", "0:2", "--orbit", "20"}));
  ASSERT_TRUE(one.ExitedWith(0)) << one.Describe();
  for (const char* k : {"0", "1", "2"}) {
    const std::string a = test::ReadFile(dir / (std::string("two.") + k + ".pfm"));
    EXPECT_FALSE(a.empty());
    EXPECT_EQ(a, test::ReadFile(dir / (std::string("one.") + k + ".pfm"))) << "frame " << k;
  }
  EXPECT_NE(test::ReadFile(dir / "one.0.pfm"), test::ReadFile(dir / "one.1.pfm"));  // the camera turned
}

TEST(Mpi, SetupErrorsAreReportedOnceOrByRank) {
  const test::TempFolder dir("mpi-setup");
  ProcessResult missing = MpiRun(3, Frame(dir / "absent.gltf", "cpu", dir / "x.png"));
  EXPECT_TRUE(missing.ExitedWith(1)) << missing.Describe();
  const std::string error = "vkpt: error: " + dir / "absent.gltf";
  const size_t first = missing.err.find(error);
  ASSERT_NE(first, std::string::npos) << missing.err;
  EXPECT_EQ(missing.err.find(error, first + 1), std::string::npos) << "reported more than once:\n" << missing.err;

  ProcessResult one =
      MpiRunTwo(Frame(kCornell, "cpu", dir / "x.png"), {"--backend", "vulkan", "--device", "no-such-device"});
  EXPECT_TRUE(one.ExitedWith(1)) << one.Describe();
  EXPECT_NE(one.err.find("vkpt: error: rank 1 ("), std::string::npos) << one.err;
  EXPECT_NE(one.err.find("no-such-device"), std::string::npos) << one.err;
  EXPECT_TRUE(dir.Listing().empty()) << "left: " << testing::PrintToString(dir.Listing());
}

TEST(Mpi, RanksGivenDifferentFramesAreRefused) {
  const test::TempFolder dir("mpi-frames");
  ProcessResult r = MpiRunTwo(Frame(kCornell, "cpu", dir / "x.png"), {"--seed", "10"});
  EXPECT_TRUE(r.ExitedWith(2)) << r.Describe();
  EXPECT_NE(r.err.find("different frames"), std::string::npos) << r.err;
  EXPECT_TRUE(dir.Listing().empty());
}

}  // namespace
}  // namespace vkpt::internal

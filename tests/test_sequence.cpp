// Frame sequences (app/sequence.h): --frames renders each frame from one load, posed
// k / --fps seconds into the --animation and turned by k × --orbit; frame k is
// byte-identical to a render of that frame alone; the files are numbered as --out says;
// --stats lists the frames; a long range costs nothing per frame; malformed ranges are
// usage errors.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "app/sequence.h"
#include "gltf_builder.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

using namespace test;

TEST(Sequence, FramePathsFollowTheirPattern) {
  EXPECT_EQ(FramePath("turn.png", 7), "turn.0007.png");
  EXPECT_EQ(FramePath("out/turn.###.exr", 7), "out/turn.007.exr");
  EXPECT_EQ(FramePath("frame_#.pfm", 12345), "frame_12345.pfm");       // wider than its run
  EXPECT_EQ(FramePath("v1.2/turn", 3), "v1.2/turn.0003");              // a dot in the folder only
  EXPECT_EQ(FramePath("take#2/shot.png", 3), "take#2/shot.0003.png");  // a '#' in the folder only
  EXPECT_EQ(FrameCount({2, 9, 3}), 3u);
  EXPECT_EQ(FrameNumber({2, 9, 3}, 2), 8u);
  EXPECT_EQ(FrameCount({4, 4, 1}), 1u);
  EXPECT_EQ(FrameCount({0, 4294967295u, 1}), 4294967296u);
  EXPECT_EQ(FrameNumber({0, 4294967295u, 1}, 4294967295u), 4294967295u);
}

std::vector<std::string> Render(const std::string& scene, const std::string& out, std::vector<std::string> extra) {
  std::vector<std::string> args = {"--scene",     scene,       "--backend", "cpu",      "--width", "24",
                                   "--height",    "16",        "--spp",     "4",        "--out",   out,
                                   "--look-from", "0.5,0.5,3", "--look-at", "0.5,0.5,0"};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

TEST(Sequence, EachFrameIsTheRenderOfItsTimeAlone) {
  const TempFile model(SlidingTriangle());
  const std::string dir = TempPath("sequence");
  std::filesystem::create_directories(dir);
  const std::string stats = dir + "/s.json";
  ProcessResult r = RunVkpt(Render(model.path, dir + "/slide.###.pfm",
                                   {"--animation", "slide", "--frames", "0:4:2", "--fps", "4", "--stats", stats}));
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  for (const char* line : {"vkpt: frame 0 (1 of 3, 0 s): pose", "vkpt: frame 2 (2 of 3, 0.5 s)",
                           "vkpt: frame 4 (3 of 3, 1 s)", "vkpt: 3 of 3 frames in"})
    EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
  std::vector<std::string> frames;
  for (const char* f : {"/slide.000.pfm", "/slide.002.pfm", "/slide.004.pfm"}) {
    ASSERT_TRUE(std::filesystem::exists(dir + f)) << f;
    frames.push_back(ReadFile(dir + f));
  }
  EXPECT_NE(frames[0], frames[1]);  // the triangle moved
  // Frame 2 alone: --at 2 / 4 s.
  ProcessResult alone = RunVkpt(Render(model.path, dir + "/alone.pfm", {"--animation", "slide", "--at", "0.5"}));
  ASSERT_TRUE(alone.ExitedWith(0)) << alone.Describe();
  EXPECT_TRUE(ReadFile(dir + "/alone.pfm") == frames[1]) << "frame 2 differs from its render alone";
  const std::string json = ReadFile(stats);
  EXPECT_EQ(json.rfind("{\"frames\":[{", 0), 0u) << json.substr(0, 200);
  for (const char* t : {"\"animation_time\":0}", "\"animation_time\":0.5}", "\"animation_time\":1}"})
    EXPECT_NE(json.find(t), std::string::npos) << t;
  std::filesystem::remove_all(dir);
}

TEST(Sequence, TurntableFrameIsTheOrbitAlone) {
  const TempFile model(SlidingTriangle());
  const std::string dir = TempPath("turntable");
  std::filesystem::create_directories(dir);
  ProcessResult r = RunVkpt(Render(model.path, dir + "/turn.pfm", {"--frames", "0:3", "--orbit", "30"}));
  ASSERT_TRUE(r.ExitedWith(0)) << r.Describe();
  ProcessResult alone = RunVkpt(Render(model.path, dir + "/alone.pfm", {"--orbit", "90"}));
  ASSERT_TRUE(alone.ExitedWith(0)) << alone.Describe();
  EXPECT_TRUE(ReadFile(dir + "/alone.pfm") == ReadFile(dir + "/turn.0003.pfm")) << "frame 3 differs from --orbit 90";
  EXPECT_FALSE(ReadFile(dir + "/turn.0000.pfm") == ReadFile(dir + "/turn.0003.pfm"));
  // Frame 0 is turned by nothing: it is the render without --orbit, bit for bit.
  ProcessResult still = RunVkpt(Render(model.path, dir + "/still.pfm", {}));
  ASSERT_TRUE(still.ExitedWith(0)) << still.Describe();
  EXPECT_TRUE(ReadFile(dir + "/still.pfm") == ReadFile(dir + "/turn.0000.pfm")) << "frame 0 differs from no --orbit";
  std::filesystem::remove_all(dir);
}

// A sequence keeps nothing per frame: a million-frame range begins at once (checking
// every frame's file beforehand took 8 s), and 2,000 frames peak where 20 do.
TEST(Sequence, LongSequencesBeginAtOnceAndHoldTheirMemory) {
  const TempFile model(SlidingTriangle());
  const test::TempFolder dir("sequence-long");
  const auto frames = [&](const std::string& range, const ChildSignals& signals = {}) {
    return RunVkpt(Render(model.path, dir / "f.######.png",
                          {"--animation", "slide", "--frames", range, "--width", "4", "--height", "4", "--spp", "1"}),
                   300.0, "", {}, {}, signals);
  };
  ProcessResult million = frames("0:999999", {.after = "vkpt: frame 0 (1 of 1000000,", .signals = {SIGINT}});
  EXPECT_TRUE(million.ExitedWith(130)) << million.Describe();
  EXPECT_LT(million.sentAt, 4.0) << "the first frame came late";
#if defined(VKPT_ADDRESS_SANITIZER)
  return;  // AddressSanitizer's quarantine holds freed memory: the peak grows with every allocation
#endif
  const ProcessResult few = frames("0:19"), many = frames("0:1999");
  ASSERT_TRUE(few.ExitedWith(0) && many.ExitedWith(0)) << few.Describe() << many.Describe();
  EXPECT_LT(many.peakRssKiB, few.peakRssKiB + 2048) << "from " << few.peakRssKiB << " KiB";
}

TEST(Sequence, MalformedRangesAreUsageErrors) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--frames", "5"}, "--frames expects FIRST:LAST[:STEP], got \"5\""},
      {{"--frames", "1:2:3:4"}, "--frames expects FIRST:LAST[:STEP]"},
      {{"--frames", "3:1"}, "--frames: the last frame, 1, comes before the first, 3"},
      {{"--frames", "0:4:0"}, "--frames"},
      {{"--frames", "0:4", "--at", "1", "--animation", "a"}, "--frames gives each frame its time"},
      {{"--frames", "0:4", "--compare"}, "--compare checks one image; drop --frames"},
      {{"--fps", "0"}, "--fps"},
  };
  for (const auto& [extra, message] : cases) {
    std::vector<std::string> args = {"--scene", "s.gltf"};
    args.insert(args.end(), extra.begin(), extra.end());
    ProcessResult r = RunVkpt(args);
    EXPECT_TRUE(r.ExitedWith(2)) << r.Describe();
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace vkpt::internal

// Honest output: when vkpt cannot write its image completely (a file-size limit standing
// in for a full disk), it exits 1 naming the file and the OS error, and leaves neither a
// partial image nor a temporary file behind; an existing image stays as it was. A
// checkpoint that cannot be written is reported once and the render goes on; renders
// writing the same file at once leave one of their images, whole.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "test_util.h"

namespace vkpt::internal {
namespace {

namespace fs = std::filesystem;
using test::DirectoryListing;
using test::FreshTempDirectory;
using test::ProcessResult;

// Below every format's size at 48x48 pixels but above zero, so the writer sees a short
// write first and the error (EFBIG) on the next call.
constexpr uint64_t kFileSizeLimit = 1024;

ProcessResult RenderCornell(const std::string& out, std::optional<uint64_t> fileSizeLimit) {
  return test::RunVkpt({"--scene", test::SourcePath("scenes/cornell.gltf"), "--backend", "cpu", "--width", "48",
                        "--height", "48", "--spp", "1", "--out", out},
                       60.0, "", {}, {.fileSize = fileSizeLimit});
}

void ExpectWriteError(const ProcessResult& r, const std::string& out) {
  EXPECT_TRUE(r.ExitedWith(1)) << r.Describe();
  const size_t lastLine = r.err.rfind('\n', r.err.size() - 2) + 1;  // 0 for a single line
  const std::string error = "vkpt: error: " + out + ": ";
  EXPECT_EQ(r.err.compare(lastLine, error.size(), error), 0) << r.err;
  EXPECT_NE(r.err.find("File too large"), std::string::npos) << "the OS error is not named: " << r.err;
}

class WriteFailure : public ::testing::TestWithParam<std::string> {};

TEST_P(WriteFailure, FileSizeLimitExitsOneAndLeavesNoFile) {
  // A new, empty directory per test, so "nothing left behind" can be checked exactly.
  const std::string dir = FreshTempDirectory("write-failure-" + GetParam());
  const std::string out = dir + "/cornell." + GetParam();
  // Without the limit the image is written and is larger than the limit: the limit is
  // what makes the next run fail.
  ProcessResult full = RenderCornell(out, std::nullopt);
  ASSERT_TRUE(full.ExitedWith(0)) << full.Describe();
  ASSERT_GT(fs::file_size(out), kFileSizeLimit);
  fs::remove(out);

  ExpectWriteError(RenderCornell(out, kFileSizeLimit), out);
  EXPECT_EQ(DirectoryListing(dir), std::vector<std::string>{}) << "a partial image or a temporary file was left behind";
  fs::remove_all(dir);
}

TEST_P(WriteFailure, FileSizeLimitKeepsThePreviousImage) {
  const std::string dir = FreshTempDirectory("write-failure-keep-" + GetParam());
  const std::string out = dir + "/cornell." + GetParam();
  const std::string previous = "the previous render, which a failed write must not touch\n";
  std::ofstream(out, std::ios::binary) << previous;

  ExpectWriteError(RenderCornell(out, kFileSizeLimit), out);
  EXPECT_EQ(test::ReadFile(out), previous);
  EXPECT_EQ(DirectoryListing(dir), std::vector<std::string>{"cornell." + GetParam()}) << "a temporary file was left behind";
  fs::remove_all(dir);
}

// Every checkpoint meets the full disk: one warning line, the passes go on to the end,
// then the final write fails as any write does.
TEST(WriteFailure, FullDiskDuringCheckpointsIsReportedOnceAndTheRenderGoesOn) {
  const std::string dir = FreshTempDirectory("write-failure-full-disk");
  const std::string out = dir + "/cornell.pfm";
  ProcessResult r =
      test::RunVkpt({"--scene", test::SourcePath("scenes/cornell.gltf"), "--backend", "cpu", "--width", "48",
                     "--height", "48", "--time", "1.5", "--checkpoint", "0.001", "-v", "--out", out},
                    60.0, "", {}, {.fileSize = kFileSizeLimit});
  ExpectWriteError(r, out);
  const std::string warning = "vkpt: warning: a checkpoint could not be written, the render goes on: " + out +
                              ": write failed: File too large\n";
  EXPECT_NE(r.err.find(warning), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("checkpoint"), r.err.rfind("checkpoint")) << "reported more than once: " << r.err;
  size_t passes = 0;
  for (size_t at = r.out.find("  pass "); at != std::string::npos; at = r.out.find("  pass ", at + 1)) ++passes;
  EXPECT_GE(passes, 2u) << "the render did not go on: " << r.out;
  EXPECT_EQ(DirectoryListing(dir), std::vector<std::string>{}) << "a partial image or a temporary file was left behind";
  fs::remove_all(dir);
}

// Eight renders of different seeds writing the same --out at once: the file is one of
// their images, whole, and nothing else is left.
TEST(WriteFailure, ConcurrentRendersOfOneFileLeaveOneWholeImage) {
  const std::string dir = FreshTempDirectory("write-concurrent");
  auto args = [&](int seed, const std::string& out) {
    return std::vector<std::string>{"--scene",   test::SourcePath("scenes/cornell.gltf"),
                                    "--backend", "cpu",
                                    "--threads", "1",
                                    "--width",   "96",
                                    "--height",  "96",
                                    "--spp",     "4",
                                    "--seed",    std::to_string(seed),
                                    "--out",     out};
  };
  std::vector<std::thread> renders;
  std::vector<ProcessResult> results(8);
  for (int seed = 0; seed < 8; ++seed)
    renders.emplace_back([&, seed] { results[seed] = test::RunVkpt(args(seed + 1, dir + "/shared.pfm")); });
  for (std::thread& t : renders) t.join();
  for (const ProcessResult& r : results) EXPECT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_EQ(DirectoryListing(dir), std::vector<std::string>{"shared.pfm"});
  const std::string written = test::ReadFile(dir + "/shared.pfm");
  int matches = 0;
  for (int seed = 1; seed <= 8; ++seed) {
    const std::string reference = dir + "/reference.pfm";
    ASSERT_TRUE(test::RunVkpt(args(seed, reference)).ExitedWith(0));
    matches += test::ReadFile(reference) == written;
  }
  EXPECT_EQ(matches, 1) << "the file is not one render's image";
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Formats, WriteFailure, ::testing::Values("png", "pfm", "exr"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace vkpt::internal

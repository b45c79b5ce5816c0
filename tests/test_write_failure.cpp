// Honest output: when vkpt cannot write its image completely (a file-size limit standing
// in for a full disk), it exits 1 naming the file and the OS error, and leaves neither a
// partial image nor a temporary file behind; an existing image stays as it was.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "test_util.h"

namespace vkpt {
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
  EXPECT_EQ(r.err.rfind("vkpt: error: " + out + ": ", 0), 0u) << r.err;
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

INSTANTIATE_TEST_SUITE_P(Formats, WriteFailure, ::testing::Values("png", "pfm", "exr"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace vkpt

// WriteFileAtomically: the bytes arrive exactly, replace an existing file, and a failure
// names the file and the OS error and leaves no temporary file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "test_util.h"
#include "util/atomic_write.h"
#include "util/error.h"

namespace vkpt {
namespace {

namespace fs = std::filesystem;
using test::DirectoryListing;
using test::FreshTempDirectory;

TEST(AtomicWrite, WritesExactlyTheBytesAndReplacesTheOldFile) {
  const std::string dir = FreshTempDirectory("atomic-bytes");
  const std::string path = dir + "/out.bin";
  std::vector<uint8_t> bytes(3 << 20);  // several MiB: more than one write(2) may take
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = uint8_t(i * 7 + (i >> 11));
  std::ofstream(path) << "old contents";
  WriteFileAtomically(path, bytes);
  EXPECT_TRUE(test::ReadFile(path) == std::string(bytes.begin(), bytes.end()));
  EXPECT_EQ(DirectoryListing(dir), std::vector<std::string>{"out.bin"});
  fs::remove_all(dir);
}

TEST(AtomicWrite, MissingDirectoryNamesTheFileAndTheError) {
  const std::string path = test::TempPath("atomic-no-such-dir") + "/out.bin";
  try {
    WriteFileAtomically(path, std::vector<uint8_t>{1, 2, 3});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos) << e.what();
  }
}

TEST(AtomicWrite, FailedRenameRemovesTheTemporary) {
  // The destination is a directory: everything succeeds up to rename(2), which fails.
  const std::string dir = FreshTempDirectory("atomic-rename");
  const std::string path = dir + "/out.bin";
  fs::create_directory(path);
  try {
    WriteFileAtomically(path, std::vector<uint8_t>{1, 2, 3});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("Is a directory"), std::string::npos) << e.what();
  }
  EXPECT_EQ(DirectoryListing(dir), std::vector<std::string>{"out.bin"}) << "the temporary file was left behind";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vkpt

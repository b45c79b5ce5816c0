// WriteFileAtomically: the bytes arrive exactly, replace an existing file, and a failure
// names the file and the OS error and leaves no temporary file; a writer killed at any
// moment (SIGKILL) leaves the previous file or the new one, whole, and the next write
// removes any temporary it left, but not one a live writer holds.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "test_util.h"
#include "util/atomic_write.h"
#include "util/error.h"

namespace vkpt::internal {
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

using Writer = void (*)(const std::string& path, std::span<const uint8_t> bytes);

// The mutant: the file written in place, as fopen("wb") and fwrite do.
void WriteInPlace(const std::string& path, std::span<const uint8_t> bytes) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) std::abort();
  for (size_t done = 0; done < bytes.size(); done += 1 << 16)
    std::fwrite(bytes.data() + done, 1, std::min<size_t>(1 << 16, bytes.size() - done), f);
  std::fclose(f);
}

// Whether files in `dir` can be created without a name (Linux's O_TMPFILE, which ext4,
// xfs, btrfs and tmpfs have; WriteFileAtomically falls back to a named temporary).
bool UnnamedFilesWork(const std::string& dir) {
  const int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
  if (fd < 0) return false;
  ::close(fd);
  return true;
}

struct KillOutcome {
  int torn = 0;                // kills after which the file was neither version, whole
  int leftovers = 0;           // kills after which another file was in the folder
  int mostLeftovers = 0;       // the most other files seen in the folder after a kill
  int leftoversAtTheEnd = -1;  // other files after one more write once the kills are over
  bool unnamedFiles = false;   // UnnamedFilesWork in that folder
};

// `kills` times: a child process writes two 4 MiB versions of a file in turn, without
// end, and is killed by SIGKILL 10–100 ms after it starts (a random moment of some write:
// the child does nothing else). After each kill the folder is inspected and left as it
// is for the next child; after the last, `write` writes the file once more.
KillOutcome KillWhileWriting(Writer write, int kills) {
  const std::string dir = FreshTempDirectory("atomic-kill");
  const std::string path = dir + "/image.bin";
  std::vector<uint8_t> versions[2];
  for (int v = 0; v < 2; ++v) {
    versions[v].resize(4 << 20);
    for (size_t i = 0; i < versions[v].size(); ++i) versions[v][i] = uint8_t(i * (v ? 13 : 7) + (i >> 12));
  }
  std::mt19937 random(2026);
  KillOutcome outcome;
  outcome.unnamedFiles = UnnamedFilesWork(dir);
  for (int k = 0; k < kills; ++k) {
    const pid_t pid = fork();
    if (pid == 0) {
      for (int v = 0;; v ^= 1) write(path, versions[v]);
    }
    std::this_thread::sleep_for(std::chrono::microseconds(std::uniform_int_distribution(10000, 100000)(random)));
    kill(pid, SIGKILL);
    waitpid(pid, nullptr, 0);
    if (fs::exists(path)) {
      const std::string bytes = test::ReadFile(path);
      const bool whole = bytes == std::string(versions[0].begin(), versions[0].end()) ||
                         bytes == std::string(versions[1].begin(), versions[1].end());
      outcome.torn += !whole;
    }
    const int others = int(DirectoryListing(dir).size()) - fs::exists(path);
    outcome.leftovers += others > 0;
    outcome.mostLeftovers = std::max(outcome.mostLeftovers, others);
  }
  write(path, versions[0]);
  outcome.leftoversAtTheEnd = int(DirectoryListing(dir).size()) - 1;
  fs::remove_all(dir);
  return outcome;
}

// The mutant of the sweep: writes as WriteFileAtomically does but leaves every other
// file in the folder alone, as a writer without RemoveAbandonedTemporaries would.
void WriteWithoutSweeping(const std::string& path, std::span<const uint8_t> bytes) {
  const std::string tmp = path + ".partial-0123456789abcdef";
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) std::abort();
  std::fwrite(bytes.data(), 1, bytes.size(), f);
  std::fclose(f);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) std::abort();
  std::FILE* again = std::fopen((path + ".partial-fedcba9876543210").c_str(), "wb");  // "killed" before renaming
  if (!again) std::abort();
  std::fclose(again);
}

TEST(AtomicWrite, KilledAtRandomMomentsLeavesAWholeFileAndNoLastingTemporary) {
  const KillOutcome atomic = KillWhileWriting(WriteFileAtomically, 20);
  EXPECT_EQ(atomic.torn, 0) << "of 20 kills";
  EXPECT_EQ(atomic.leftoversAtTheEnd, 0) << "the last write did not remove the temporaries killed writers left";
  // Each child's first write removed what the one before left: nothing piles up.
  EXPECT_LE(atomic.mostLeftovers, 1);
  // With O_TMPFILE a temporary has a name only between linkat and rename: a kill rarely
  // falls there (it does when the writer is preempted in between, on a busy machine).
  if (atomic.unnamedFiles) {
    EXPECT_LE(atomic.leftovers, 5) << "of 20 kills";
  }
  std::printf("  %d of 20 kills left a temporary (O_TMPFILE %s)\n", atomic.leftovers,
              atomic.unnamedFiles ? "works" : "does not work here");
  // The harness has teeth: the same kills tear a file written in place, and temporaries
  // pile up where nothing removes them.
  const KillOutcome inPlace = KillWhileWriting(WriteInPlace, 20);
  EXPECT_GE(inPlace.torn, 10) << "of 20 kills";
  const KillOutcome unswept = KillWhileWriting(WriteWithoutSweeping, 3);
  EXPECT_GT(unswept.leftoversAtTheEnd, 0);
}

TEST(AtomicWrite, RemovesOnlyTemporariesNoLiveWriterHolds) {
  const std::string dir = FreshTempDirectory("atomic-sweep");
  const std::string path = dir + "/out.bin";
  const std::string abandoned = path + ".partial-00000000deadbeef";
  const std::string held = path + ".partial-00000000feedf00d";
  const std::vector<std::string> notOurs = {path + ".partial-notours", path + ".partial-0000000000000000x",
                                            dir + "/other.bin.partial-00000000deadbeef"};
  for (const std::string& name : notOurs) std::ofstream(name) << "someone else's";
  std::ofstream(abandoned) << "abandoned";
  std::ofstream(held) << "in progress";
  // A live writer: the lock is taken through a descriptor of its own.
  const int fd = ::open(held.c_str(), O_RDONLY | O_CLOEXEC);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  WriteFileAtomically(path, std::vector<uint8_t>{1, 2, 3});
  EXPECT_FALSE(fs::exists(abandoned));
  EXPECT_TRUE(fs::exists(held));
  for (const std::string& name : notOurs) EXPECT_TRUE(fs::exists(name)) << name;
  ::close(fd);
  WriteFileAtomically(path, std::vector<uint8_t>{4, 5, 6});
  EXPECT_FALSE(fs::exists(held)) << "its writer is gone";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vkpt::internal

// TempFileGuard: the temporary file goes when the guard is destroyed and when SIGINT or
// SIGTERM ends the process while the guard is held (the process still dies of that
// signal); a dismissed file stays; an ignored signal stays ignored; and once the guard
// is gone, the signals' actions are what they were before.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>

#include "test_util.h"
#include "util/temp_file_guard.h"

namespace vkpt::internal {
namespace {

namespace fs = std::filesystem;

std::string MakeFile(const std::string& name) {
  const std::string path = test::TempPath(name);
  std::ofstream(path) << "half an image";
  return path;
}

// Runs `body` in a forked child (a signal then ends the child, not the test) and returns
// its wait status; a child that returns from `body` exits 0.
int StatusOfChild(const std::function<void()>& body) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    body();
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

TEST(TempFileGuard, DestructionRemovesTheFile) {
  const std::string path = MakeFile("guard-destroyed");
  { TempFileGuard guard(path); }
  EXPECT_FALSE(fs::exists(path));
}

TEST(TempFileGuard, DismissedFileStays) {
  const std::string path = MakeFile("guard-dismissed");
  {
    TempFileGuard guard(path);
    guard.Dismiss();
  }
  EXPECT_TRUE(fs::exists(path));
  fs::remove(path);
}

TEST(TempFileGuard, OneAtATime) {
  const std::string path = MakeFile("guard-one");
  TempFileGuard guard(path);
  EXPECT_THROW(TempFileGuard second(path + "-second"), std::logic_error);
}

class TempFileGuardSignal : public ::testing::TestWithParam<int> {};

TEST_P(TempFileGuardSignal, RemovesTheFileAndDiesOfTheSignal) {
  const int sig = GetParam();
  const std::string path = MakeFile("guard-signal-" + std::to_string(sig));
  const int status = StatusOfChild([&] {
    TempFileGuard guard(path);
    ::raise(sig);
  });
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << "wait status " << status;
  EXPECT_FALSE(fs::exists(path)) << "the temporary file survived " << strsignal(sig);
  fs::remove(path);
}

TEST_P(TempFileGuardSignal, IgnoredSignalStaysIgnored) {
  const int sig = GetParam();
  const std::string path = MakeFile("guard-ignored-" + std::to_string(sig));
  const int status = StatusOfChild([&] {
    ::signal(sig, SIG_IGN);
    TempFileGuard guard(path);
    ::raise(sig);
    ::_exit(fs::exists(path) ? 0 : 1);  // skips the guard's destructor: the file must still be there
  });
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "wait status " << status;
  fs::remove(path);
}

TEST_P(TempFileGuardSignal, ActionIsRestoredAfterTheGuard) {
  const int sig = GetParam();
  const std::string path = MakeFile("guard-restored-" + std::to_string(sig));
  const int status = StatusOfChild([&] {
    {
      TempFileGuard guard(path);
      guard.Dismiss();
    }
    ::raise(sig);  // a handler still installed would remove the (dismissed) file
  });
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << "wait status " << status;
  EXPECT_TRUE(fs::exists(path));
  fs::remove(path);
}

INSTANTIATE_TEST_SUITE_P(Signals, TempFileGuardSignal, ::testing::Values(SIGINT, SIGTERM),
                         [](const ::testing::TestParamInfo<int>& info) {
                           return std::string(info.param == SIGINT ? "SIGINT" : "SIGTERM");
                         });

}  // namespace
}  // namespace vkpt::internal

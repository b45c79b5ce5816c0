// Every input a fuzz target (tests/fuzz/) ever found crashing, hanging or over-allocating
// is kept in tests/fuzz/regressions/<target>/ and replayed here in-process through that
// target's entry point, the way the target runs it (tests/fuzz/fuzz_input.h for the
// loader, fuzz_bodies.h for the others): it must return or throw its documented error
// type, within 5 seconds (the fuzzer's own -timeout) and 1 GiB. A crash ends the test
// process and so fails the test; in the sanitizer build (VKPT_SANITIZE) any memory error
// does too.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <string>
#include <thread>
#include <typeinfo>
#include <vector>

#include "fuzz/fuzz_bodies.h"
#include "fuzz/fuzz_input.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

namespace fs = std::filesystem;

// The fuzzer's own limits (tests/fuzz/run.sh): 5 s per input and 1 GiB per allocation.
const auto kTimeLimit = std::chrono::seconds(static_cast<int>(5 * test::kTimeScale));
constexpr long kMemoryLimitMiB = 1024;

struct Regression {
  std::string target;  // loader, env, texture, pfm, options, draco, meshopt
  std::string path;
  std::string name;  // test name
};

void PrintTo(const Regression& r, std::ostream* os) { *os << fs::path(r.path).filename().string(); }

std::vector<Regression> DiscoverRegressions() {
  std::vector<Regression> out;
  for (const char* target : {"loader", "env", "texture", "pfm", "options", "draco", "meshopt"}) {
    const fs::path dir = test::SourcePath(std::string("tests/fuzz/regressions/") + target);
    if (!fs::is_directory(dir)) continue;
    for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
      if (!e.is_regular_file()) continue;
      std::string name = target + std::string("_") + e.path().filename().string();
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      out.push_back({target, e.path().string(), name});
    }
  }
  std::sort(out.begin(), out.end(), [](const Regression& a, const Regression& b) { return a.path < b.path; });
  return out;
}

long PeakRssMiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024;  // Linux reports KiB
}

// Ends the process, naming the input, when the load is not over within the limit: a
// hang fails its test at once instead of stalling the suite until ctest's timeout.
class Watchdog {
 public:
  Watchdog(std::string what, std::chrono::seconds limit)
      : thread_([this, what = std::move(what), limit] {
          std::unique_lock<std::mutex> lock(mutex_);
          if (!done_cv_.wait_for(lock, limit, [this] { return done_; })) {
            std::fprintf(stderr, "FAILED: %s: still loading after %lld s (a hang)\n", what.c_str(),
                         static_cast<long long>(limit.count()));
            std::fflush(stderr);
            std::_Exit(1);
          }
        }) {}
  ~Watchdog() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    done_cv_.notify_one();
    thread_.join();
  }

 private:
  std::mutex mutex_;
  std::condition_variable done_cv_;
  bool done_ = false;
  std::thread thread_;  // last: starts once the members it uses exist
};

// Runs the input as fuzz_<target> does: what came of it, or the exception that is a
// finding (anything but the entry point's documented error type).
std::string Replay(const std::string& target, const std::string& bytes) {
  if (target == "loader") {
    const std::string dir = fuzz::MakePrivateDir("vkpt-fuzz-regression");
    std::string error;
    const bool loaded = fuzz::LoadInput(dir, bytes, &error);
    ::rmdir(dir.c_str());
    return "as " + fuzz::InputFileName(bytes) + ": " + (loaded ? "loaded" : "vkpt::internal::Error: " + error);
  }
  try {
    if (target == "options") {
      try {
        fuzz::RunOptions(bytes);
      } catch (const UsageError& e) {
        return std::string("vkpt::internal::UsageError: ") + e.what();
      }
      return "parsed";
    }
    if (target == "env") fuzz::RunEnv(bytes);
    if (target == "texture") fuzz::RunTexture(bytes);
    if (target == "pfm") fuzz::RunPfm(bytes);
    if (target == "draco") fuzz::RunDraco(bytes);
    if (target == "meshopt") fuzz::RunMeshopt(bytes);
  } catch (const Error& e) {
    return std::string("vkpt::internal::Error: ") + e.what();
  }
  return "decoded";
}

class FuzzRegression : public ::testing::TestWithParam<Regression> {};

TEST_P(FuzzRegression, EndsCleanlyWithinFiveSeconds) {
  const Regression& r = GetParam();
  std::ifstream in(r.path, std::ios::binary);
  ASSERT_TRUE(in) << "cannot read " << r.path;
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const long rssBefore = PeakRssMiB();
  const auto start = std::chrono::steady_clock::now();
  {
    Watchdog watchdog(r.path, kTimeLimit);
    try {
      std::printf("%s: %s\n", r.name.c_str(), Replay(r.target, bytes).c_str());
    } catch (const std::exception& e) {
      ADD_FAILURE() << r.target << " threw " << typeid(e).name() << ", not its documented error: " << e.what();
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%.3f s, peak RSS %ld -> %ld MiB\n", seconds, rssBefore, PeakRssMiB());
  EXPECT_LT(PeakRssMiB() - rssBefore, kMemoryLimitMiB) << "loading took too much memory";
}

INSTANTIATE_TEST_SUITE_P(Kept, FuzzRegression, ::testing::ValuesIn(DiscoverRegressions()),
                         [](const ::testing::TestParamInfo<Regression>& info) { return info.param.name; });

}  // namespace
}  // namespace vkpt::internal

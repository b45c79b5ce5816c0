// What every libFuzzer target here shares (fuzz_loader.cpp set the conventions): the
// entry point's documented error type is the expected failure, and any other exception
// is a finding, reported by aborting with its type and message. Crashes, sanitizer
// reports, slow inputs and large allocations are libFuzzer's to catch (run.sh sets its
// -timeout, -rss_limit_mb and -malloc_limit_mb).
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>
#include <typeinfo>

#include "fuzz_input.h"

namespace vkpt::internal::fuzz {

// Runs `body`; an `Expected` exception is a clean refusal, anything else aborts.
template <class Expected, class Body>
void ExpectOnly(const char* target, const char* expected, Body&& body) {
  try {
    body();
  } catch (const Expected&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: threw %s, not %s: %s\n", target, typeid(e).name(), expected, e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "%s: threw something that is not a std::exception\n", target);
    std::abort();
  }
}

// A private directory (MakePrivateDir) made once per process and removed at exit, for
// targets whose entry point takes a path.
inline const std::string& ScratchDir(const char* prefix) {
  static const std::string dir = [prefix] {
    std::string d = MakePrivateDir(prefix);
    std::atexit([] { ::rmdir(ScratchDir(nullptr).c_str()); });
    return d;
  }();
  return dir;
}

// Writes `bytes` to `path`; removes it when destroyed.
class TempInput {
 public:
  TempInput(std::string path, std::string_view bytes) : path_(std::move(path)) {
    std::FILE* f = std::fopen(path_.c_str(), "wb");
    if (!f) std::abort();
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    if (std::fclose(f) != 0 || !written) {
      std::fprintf(stderr, "fuzz: cannot write %s\n", path_.c_str());
      std::abort();
    }
  }
  ~TempInput() { std::remove(path_.c_str()); }
  TempInput(const TempInput&) = delete;
  TempInput& operator=(const TempInput&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

inline std::string_view AsText(const uint8_t* data, size_t size) { return {reinterpret_cast<const char*>(data), size}; }

}  // namespace vkpt::internal::fuzz

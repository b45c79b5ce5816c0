// The end of untrusted bytes ends stb's decode (issue 29): a Radiance header that never
// ends and run-length data cut short each make vkpt exit 1 within a second, naming the
// file. The readers vkpt shipped or could ship wrong (image/stb_source.h) are copied here,
// wrong, as mutants the same check must catch: one that invents bytes past the end, and
// one that reports the end but lets stb go on with zeros.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <functional>
#include <random>
#include <span>
#include <thread>

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_HDR
#define STBI_NO_STDIO
#define STBI_MAX_DIMENSIONS 16384
#include <stb_image.h>

#include "image/image_load.h"
#include "test_util.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

using test::ProcessResult;

// A run must end within this; the child is killed at twice it.
const double kLimitSeconds = 1.0 * test::kTimeScale;

// `#?RADIANCE\n` and 3000 pseudo-random bytes: a header without its empty line.
std::string EndlessHeader() {
  std::mt19937 rng(29);
  std::string s = "#?RADIANCE\n";
  for (int i = 0; i < 3000; ++i) s += char(rng() & 0xff);
  return s;
}

// A run-length encoded map cut inside its pixel data.
std::string CutRunLengths() {
  const std::string full = test::RleHdr(64, 32);
  return full.substr(0, full.size() * 6 / 10);
}

std::string Write(const test::TempFolder& dir, const std::string& name, const std::string& bytes) {
  const std::string path = dir / name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// `decode(path)` in a forked child, killed at twice kLimitSeconds: exit 1 with the
// message of the Error it threw on stderr, or 0 if it returned.
ProcessResult DecodeInChild(const std::function<void(const std::string&)>& decode, const std::string& path) {
  int err[2];
  if (pipe(err) != 0) return {};
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    close(err[0]);
    int code = 0;
    try {
      decode(path);
    } catch (const Error& e) {
      const std::string message = std::string("vkpt: error: ") + e.what() + "\n";
      (void)!write(err[1], message.data(), message.size());
      code = 1;
    }
    _exit(code);
  }
  close(err[1]);
  ProcessResult r;
  int status = 0;
  for (;;) {
    if (waitpid(pid, &status, WNOHANG) == pid) break;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (r.seconds > 2 * kLimitSeconds && !r.timedOut) {
      r.timedOut = true;
      kill(pid, SIGKILL);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  char buffer[4096];
  for (ssize_t n; (n = read(err[0], buffer, sizeof buffer)) > 0;) r.err.append(buffer, size_t(n));
  close(err[0]);
  return r;
}

// The regression check: exit 1 within kLimitSeconds, with an error naming the file.
::testing::AssertionResult EndsPromptlyNaming(const ProcessResult& r, const std::string& path) {
  if (!r.ExitedWith(1) || r.seconds > kLimitSeconds || r.err.find("vkpt: error: " + path + ": ") == std::string::npos)
    return ::testing::AssertionFailure() << "after " << r.seconds << " s: " << r.Describe();
  return ::testing::AssertionSuccess() << "exit 1 after " << r.seconds << " s: " << r.err;
}

// ---------------------------------------------------------------------------------------
// Mutants: copies of image/stb_source.h's reader with its end-of-data handling broken.

// As vkpt shipped before issue 29: past the end, a full read of invented 0xFF bytes, so
// stb never reaches its end-of-file state and its Radiance header loop never ends.
struct InventsBytesSource {
  std::span<const unsigned char> bytes;
  size_t pos = 0;
  static int Read(void* user, char* data, int size) {
    auto* s = static_cast<InventsBytesSource*>(user);
    const size_t n = std::min(size_t(size), s->bytes.size() - s->pos);
    std::copy_n(s->bytes.data() + s->pos, n, data);
    s->pos += n;
    std::fill(data + n, data + size, '\xff');
    return size;
  }
  static void Skip(void* user, int n) {
    auto* s = static_cast<InventsBytesSource*>(user);
    s->pos = std::min(s->bytes.size(), s->pos + size_t(std::max(n, 0)));
  }
  static int Eof(void* user) {
    auto* s = static_cast<InventsBytesSource*>(user);
    return s->pos >= s->bytes.size();
  }
};

// The reader without its end-of-data check: short reads, truthful, but stb goes on past
// the end with zeros, and a run-length count of 0 makes no progress.
struct NoEndCheckSource : InventsBytesSource {
  static int Read(void* user, char* data, int size) {
    auto* s = static_cast<NoEndCheckSource*>(user);
    const size_t n = std::min(size_t(size), s->bytes.size() - s->pos);
    std::copy_n(s->bytes.data() + s->pos, n, data);
    s->pos += n;
    return int(n);
  }
};

// image_load.cpp's DecodeHdr with the reader `Source`.
template <typename Source>
void DecodeHdrWith(const std::string& path) {
  const std::string file = test::ReadFile(path);
  const std::span<const unsigned char> bytes(reinterpret_cast<const unsigned char*>(file.data()), file.size());
  const stbi_io_callbacks io{&Source::Read, &Source::Skip, &Source::Eof};
  int width = 0, height = 0, channels = 0;
  Source header{bytes};
  if (!stbi_info_from_callbacks(&io, &header, &width, &height, &channels))
    throw Error(path + ": not a Radiance HDR file (" + stbi_failure_reason() + ")");
  Source body{bytes};
  float* rgb = stbi_loadf_from_callbacks(&io, &body, &width, &height, &channels, 3);
  if (!rgb) throw Error(path + ": cannot decode the Radiance HDR data (" + stbi_failure_reason() + ")");
  stbi_image_free(rgb);
}

void ReadEnvironment(const std::string& path) {
  std::vector<std::string> warnings;
  ReadEnvironmentImage(
      path, [](uint64_t, const std::string&) {}, &warnings);
}

// ---------------------------------------------------------------------------------------

TEST(DecoderEnd, EndlessRadianceHeaderEndsVkptWithinASecond) {
  test::TempFolder dir("decoder-end-header");
  const std::string bad = Write(dir, "bad.hdr", EndlessHeader());
  ASSERT_EQ(test::ReadFile(bad).size(), 3011u);
  const ProcessResult r = test::RunVkpt(
      {"--scene", test::SourcePath("scenes/cornell.gltf"), "--env", bad, "--out", dir / "out.png"}, 2 * kLimitSeconds);
  EXPECT_TRUE(EndsPromptlyNaming(r, bad));
  EXPECT_NE(r.err.find("is truncated (it ends inside the header)"), std::string::npos) << r.err;
  EXPECT_EQ(dir.Listing(), std::vector<std::string>{"bad.hdr"});
}

TEST(DecoderEnd, CutRunLengthDataEndsVkptWithinASecond) {
  test::TempFolder dir("decoder-end-rle");
  const std::string cut = Write(dir, "cut.hdr", CutRunLengths());
  const ProcessResult r = test::RunVkpt(
      {"--scene", test::SourcePath("scenes/cornell.gltf"), "--env", cut, "--out", dir / "out.png"}, 2 * kLimitSeconds);
  EXPECT_TRUE(EndsPromptlyNaming(r, cut));
  EXPECT_NE(r.err.find("is truncated (it ends inside the pixel data)"), std::string::npos) << r.err;
}

// The same check on the decoder in-process, then on the two mutants: the check must pass
// for vkpt's reader and catch each mutant by its time limit.
TEST(DecoderEnd, CheckCatchesReadersThatDoNotEndTheDecode) {
#if defined(VKPT_ADDRESS_SANITIZER)
  GTEST_SKIP() << "the check's mutants are test code, 16 s under AddressSanitizer; the plain build runs it";
#endif
  test::TempFolder dir("decoder-end-mutants");
  const std::string header = Write(dir, "header.hdr", EndlessHeader());
  const std::string cut = Write(dir, "cut.hdr", CutRunLengths());
  const std::string whole = Write(dir, "whole.hdr", test::RleHdr(64, 32));
  for (const std::string& path : {header, cut})
    EXPECT_TRUE(EndsPromptlyNaming(DecodeInChild(ReadEnvironment, path), path));
  // The copy of DecodeHdr decodes a whole file with either reader: the mutants differ
  // only at the end of the data.
  EXPECT_TRUE(DecodeInChild(DecodeHdrWith<InventsBytesSource>, whole).ExitedWith(0));
  EXPECT_TRUE(DecodeInChild(DecodeHdrWith<NoEndCheckSource>, whole).ExitedWith(0));

  const ProcessResult invents = DecodeInChild(DecodeHdrWith<InventsBytesSource>, header);
  EXPECT_FALSE(EndsPromptlyNaming(invents, header));
  EXPECT_TRUE(invents.timedOut) << invents.Describe();
  const ProcessResult zeros = DecodeInChild(DecodeHdrWith<NoEndCheckSource>, cut);
  EXPECT_FALSE(EndsPromptlyNaming(zeros, cut));
  EXPECT_TRUE(zeros.timedOut) << zeros.Describe();
}

// The generated run-length file decodes to its texels exactly (runs, dumps, exponents).
TEST(DecoderEnd, RunLengthMapDecodesExactly) {
  test::TempFolder dir("decoder-end-exact");
  const std::string path = Write(dir, "map.hdr", test::RleHdr(64, 32));
  std::vector<std::string> warnings;
  const Image image = ReadEnvironmentImage(
      path, [](uint64_t, const std::string&) {}, &warnings);
  ASSERT_EQ(image.width, 64u);
  ASSERT_EQ(image.height, 32u);
  int off = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) off += image.At(uint32_t(x), uint32_t(y)) != test::RleHdrTexel(x, y);
  EXPECT_EQ(off, 0);
  EXPECT_TRUE(warnings.empty());
}

}  // namespace
}  // namespace vkpt::internal

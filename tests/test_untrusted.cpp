// A glTF is untrusted input: these tests run vkpt on files written to attack it or to
// trip it up — URIs that lead out of the scene's folder, files that never end, counts
// that would allocate gigabytes — and check that it refuses them at once, reads nothing
// it should not, stays small, and says why in a short message.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gltf/gltf_loader.h"
#include "test_util.h"
#include "util/byte_size.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

namespace fs = std::filesystem;
using test::ProcessResult;
using test::RunVkpt;

// A fresh directory for the running test, removed with everything in it.
class TempDir {
 public:
  TempDir() : path(test::FreshTempDirectory(std::string("untrusted-") + CurrentTestName())) {}
  ~TempDir() { fs::remove_all(path); }
  std::string path;

 private:
  static std::string CurrentTestName() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "-" + info->name();
    std::replace(name.begin(), name.end(), '/', '-');
    return name;
  }
};

// One triangle, (0,0,0) (1,0,0) (0,1,0), as the 36 bytes of a buffer.
std::string TriangleBytes() {
  const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  return std::string(reinterpret_cast<const char*>(p), sizeof p);
}

void WriteFile(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// A glTF whose one triangle comes from the buffer at `bufferUri`; with `imageUri`, a
// material with a base-colour texture from that image (a texture uses it).
std::string TriangleGltf(const std::string& bufferUri, const std::string& imageUri = "", bool imageUsed = true) {
  std::string j = R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":")" + bufferUri + R"("}],
    "bufferViews":[{"buffer":0,"byteLength":36}],
    "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0})";
  if (!imageUri.empty()) {
    j += imageUsed ? R"(,"material":0}]}],"materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],
      "textures":[{"source":0}],)"
                   : R"(}]}],)";
    j += R"("images":[{"uri":")" + imageUri + R"("}],)";
  } else {
    j += "}]}],";
  }
  return j + R"("nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})";
}

// Runs vkpt on `scene` with a tiny CPU render.
ProcessResult Render(const std::string& scene, const std::string& out, std::vector<std::string> extra = {},
                     const std::string& cwd = "") {
  std::vector<std::string> args = {"--scene", scene, "--out", out, "--backend", "cpu", "--width", "8", "--spp", "1"};
  args.insert(args.end(), extra.begin(), extra.end());
  return RunVkpt(args, 20.0, cwd);
}

// The error line: "vkpt: error: <scene>: ..." and nothing on stdout that looks like a result.
::testing::AssertionResult RefusedQuickly(const ProcessResult& r, const std::string& out,
                                          std::initializer_list<std::string> needles, double maxSeconds = 1.0) {
  if (!r.ExitedWith(1)) return ::testing::AssertionFailure() << "expected exit 1: " << r.Describe();
  if (r.seconds > maxSeconds) return ::testing::AssertionFailure() << "took " << r.seconds << " s: " << r.Describe();
  if (fs::exists(out)) return ::testing::AssertionFailure() << "left an output file: " << out;
  for (const std::string& n : needles)
    if (r.err.find(n) == std::string::npos)
      return ::testing::AssertionFailure() << "stderr lacks \"" << n << "\": " << r.err;
  return ::testing::AssertionSuccess() << r.err;
}

// ---------------------------------------------------------------------------------------
// Confinement: each route out of the scene's folder is refused without opening the file
// it names — the target is a FIFO, which would block a reader forever — and the same
// scene renders once --allow-external-uris lifts the rule (the FIFO replaced by data).

struct EscapeRoute {
  const char* name;
  // The uri to write, given the root directory holding scene/ and outside.bin.
  std::string (*uri)(const std::string& root);
  bool fromRootDirectory;  // run vkpt with the root as its current directory
  const char* reason;      // what the message says
};

void PrintTo(const EscapeRoute& route, std::ostream* os) { *os << route.name; }

const EscapeRoute kRoutes[] = {
    {"DotDot", [](const std::string&) { return std::string("../outside.bin"); }, false, "leads out"},
    {"PercentEncodedDotDot", [](const std::string&) { return std::string("%2e%2E%2foutside.bin"); }, false,
     "leads out"},
    {"AbsolutePath", [](const std::string& root) { return root + "/outside.bin"; }, false, "absolute path"},
    {"FileUrl", [](const std::string& root) { return "file://" + root + "/outside.bin"; }, false, "file:// URL"},
    {"SymlinkOut", [](const std::string&) { return std::string("link.bin"); }, false, "symbolic link"},
    {"CurrentDirectoryOnly", [](const std::string&) { return std::string("outside.bin"); }, true,
     "names no file in the scene's folder"},
};

class Confinement : public ::testing::TestWithParam<EscapeRoute> {};

TEST_P(Confinement, RefusedUnreadThenAllowedByOption) {
  const EscapeRoute& route = GetParam();
  TempDir root;
  ASSERT_FALSE(root.path.empty());
  fs::create_directory(root.path + "/scene");
  const std::string outside = root.path + "/outside.bin", scene = root.path + "/scene/scene.gltf";
  ASSERT_EQ(mkfifo(outside.c_str(), 0600), 0);
  fs::create_symlink("../outside.bin", root.path + "/scene/link.bin");
  const std::string uri = route.uri(root.path);
  WriteFile(scene, TriangleGltf(uri));
  const std::string cwd = route.fromRootDirectory ? root.path : "";
  const std::string out = root.path + "/out.png";

  ProcessResult refused = Render(scene, out, {}, cwd);
  EXPECT_TRUE(RefusedQuickly(refused, out, {scene + ": ", "buffers[0].uri \"" + uri + "\"", route.reason}));
  if (!route.fromRootDirectory) {
    EXPECT_NE(refused.err.find("--allow-external-uris"), std::string::npos);
  }

  fs::remove(outside);
  WriteFile(outside, TriangleBytes());
  ProcessResult refusedFile = Render(scene, out, {}, cwd);
  EXPECT_TRUE(RefusedQuickly(refusedFile, out, {"buffers[0].uri"}));
  EXPECT_EQ(refusedFile.err, refused.err) << "the message must not depend on the outside file";

  ProcessResult allowed = Render(scene, out, {"--allow-external-uris"}, cwd);
  EXPECT_TRUE(allowed.ExitedWith(0)) << allowed.Describe();
  EXPECT_TRUE(fs::exists(out));
}

INSTANTIATE_TEST_SUITE_P(EscapeRoutes, Confinement, ::testing::ValuesIn(kRoutes),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(Confinement, ImageUriOutOfTheFolderIsRefusedUnread) {
  TempDir root;
  fs::create_directory(root.path + "/scene");
  ASSERT_EQ(mkfifo((root.path + "/outside.png").c_str(), 0600), 0);
  WriteFile(root.path + "/scene/tri.bin", TriangleBytes());
  const std::string scene = root.path + "/scene/scene.gltf", out = root.path + "/out.png";
  for (bool used : {true, false}) {
    WriteFile(scene, TriangleGltf("tri.bin", "../outside.png", used));
    EXPECT_TRUE(RefusedQuickly(Render(scene, out), out, {"images[0].uri \"../outside.png\" leads out"}));
  }
}

TEST(Confinement, FilesInsideTheFolderAndItsSubfoldersAreRead) {
  TempDir root;
  fs::create_directories(root.path + "/scene/data/deeper");
  WriteFile(root.path + "/scene/data/deeper/tri bin.bin", TriangleBytes());
  fs::create_symlink("data/deeper/tri bin.bin", root.path + "/scene/inside-link.bin");
  const std::string out = root.path + "/out.png";
  for (const std::string uri : {"data/deeper/../deeper/tri%20bin.bin", "./inside-link.bin"}) {
    WriteFile(root.path + "/scene/scene.gltf", TriangleGltf(uri));
    ProcessResult r = Render(root.path + "/scene/scene.gltf", out);
    EXPECT_TRUE(r.ExitedWith(0)) << uri << ": " << r.Describe();
  }
}

// ---------------------------------------------------------------------------------------
// Files that are not regular files, as the scene and as a uri.

TEST(NotRegularFiles, AsTheSceneAreRefusedAtOnce) {
  TempDir root;
  const std::string fifo = root.path + "/fifo.gltf", dir = root.path + "/dir.gltf", out = root.path + "/o.png";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  fs::create_directory(dir);
  EXPECT_TRUE(RefusedQuickly(Render(fifo, out), out, {fifo + ": is a FIFO"}));
  EXPECT_TRUE(RefusedQuickly(Render(dir, out), out, {dir + ": is a directory"}));
  EXPECT_TRUE(RefusedQuickly(Render("/dev/zero", out), out, {"/dev/zero: is a device"}));
}

TEST(NotRegularFiles, AsAUriAreRefusedAtOnce) {
  TempDir root;
  ASSERT_EQ(mkfifo((root.path + "/fifo.bin").c_str(), 0600), 0);
  fs::create_directory(root.path + "/dir.bin");
  const std::string scene = root.path + "/scene.gltf", out = root.path + "/o.png";
  WriteFile(scene, TriangleGltf("fifo.bin"));
  EXPECT_TRUE(RefusedQuickly(Render(scene, out), out, {"buffers[0].uri \"fifo.bin\" is a FIFO"}));
  WriteFile(scene, TriangleGltf("dir.bin"));
  EXPECT_TRUE(RefusedQuickly(Render(scene, out), out, {"buffers[0].uri \"dir.bin\" is a directory"}));
  WriteFile(scene, TriangleGltf("/dev/zero"));
  EXPECT_TRUE(RefusedQuickly(Render(scene, out, {"--allow-external-uris"}), out,
                             {"buffers[0].uri \"/dev/zero\" is a device"}));
  WriteFile(root.path + "/tri.bin", TriangleBytes());
  WriteFile(scene, TriangleGltf("tri.bin", "fifo.bin"));
  EXPECT_TRUE(RefusedQuickly(Render(scene, out), out, {"images[0].uri \"fifo.bin\" is a FIFO"}));
  WriteFile(scene, TriangleGltf("tri.bin", "dir.bin"));
  EXPECT_TRUE(RefusedQuickly(Render(scene, out), out, {"images[0].uri \"dir.bin\" is a directory"}));
}

// ---------------------------------------------------------------------------------------
// Amplification: small files that ask for gigabytes are refused before they get them.

constexpr long kSmallProcessKiB = 200 * 1024;

TEST(Amplification, HugeAccessorWithoutBufferViewIsRefusedSmall) {
  TempDir root;
  const std::string scene = root.path + "/huge.gltf", out = root.path + "/o.png";
  WriteFile(scene, R"({"asset":{"version":"2.0"},"accessors":[{"componentType":5126,"count":268435455,"type":"VEC3"}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]})");
  ProcessResult r = Render(scene, out);
  EXPECT_TRUE(RefusedQuickly(r, out, {"meshes[0]", "89478485 triangles", "--max-memory"}));
  EXPECT_LT(r.peakRssKiB, kSmallProcessKiB);
}

TEST(Amplification, ThousandInstancesOfABigMeshAreRefusedSmall) {
  TempDir root;
  std::string nodes, children;
  for (int i = 1; i <= 1000; ++i) {
    nodes += R"(,{"mesh":0,"translation":[)" + std::to_string(i) + ",0,0]}";
    children += i > 1 ? "," : "";  // not `"," + std::to_string(i)`: GCC 12's false -Wrestrict (bug 105651)
    children += std::to_string(i);
  }
  const std::string scene = root.path + "/instances.gltf", out = root.path + "/o.png";
  WriteFile(scene, R"({"asset":{"version":"2.0"},"accessors":[{"componentType":5126,"count":3000000,"type":"VEC3"}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"children":[)" + children + "]}" + nodes +
                       R"(],"scenes":[{"nodes":[0]}]})");
  ProcessResult r = Render(scene, out);
  EXPECT_TRUE(RefusedQuickly(r, out, {"meshes[0] (1000000 triangles × 1000 instances"}));
  EXPECT_LT(r.peakRssKiB, kSmallProcessKiB);
}

// A sparse 2 GiB file: a reader that reads it in full shows in the peak memory.
void MakeSparseFile(const std::string& path, const std::string& head, off_t size) {
  WriteFile(path, head);
  ASSERT_EQ(truncate(path.c_str(), size), 0);
}

TEST(Amplification, TwoGigabytesOfNonGltfAreRefusedFromTheFirstBytes) {
  TempDir root;
  const std::string big = root.path + "/big.gltf", out = root.path + "/o.png";
  MakeSparseFile(big, "PK\x03\x04", off_t(2) << 30);
  ProcessResult r = Render(big, out);
  EXPECT_TRUE(RefusedQuickly(r, out, {"not a glTF file"}));
  EXPECT_LT(r.peakRssKiB, kSmallProcessKiB);
}

TEST(Amplification, JsonLargerThanTheBudgetIsRefusedFromItsSize) {
  TempDir root;
  const std::string big = root.path + "/big.gltf", out = root.path + "/o.png";
  MakeSparseFile(big, "{\"asset\":", off_t(2) << 30);
  ProcessResult r = Render(big, out, {"--max-memory", "4G"});
  EXPECT_TRUE(RefusedQuickly(r, out, {"loading the file (2 GiB) needs", "--max-memory 4 GiB"}));
  EXPECT_LT(r.peakRssKiB, kSmallProcessKiB);
}

TEST(Amplification, UnusedImageIsNotRead) {
  TempDir root;
  WriteFile(root.path + "/tri.bin", TriangleBytes());
  MakeSparseFile(root.path + "/huge.png", "\x89PNG", off_t(2) << 30);
  const std::string scene = root.path + "/scene.gltf", out = root.path + "/o.png";
  WriteFile(scene, TriangleGltf("tri.bin", "huge.png", /*imageUsed=*/false));
  ProcessResult r = Render(scene, out, {"-v"});
  EXPECT_TRUE(r.ExitedWith(0)) << r.Describe();
  EXPECT_NE(r.out.find("images[0] \"huge.png\": used by no texture, not read"), std::string::npos) << r.out;
  EXPECT_LT(r.peakRssKiB, kSmallProcessKiB);
}

TEST(Amplification, VerboseReportsTheBudget) {
  TempDir root;
  ProcessResult ok =
      Render(test::SourcePath("scenes/cornell.gltf"), root.path + "/o.png", {"--max-memory", "200M", "-v"});
  EXPECT_TRUE(ok.ExitedWith(0)) << ok.Describe();
  EXPECT_NE(ok.out.find("of --max-memory 200 MiB"), std::string::npos) << ok.out;
}

TEST(Amplification, BudgetRefusalNamesTheLimit) {
  VKPT_REQUIRE_SHARED_DATA();
  TempDir root;
  const std::string out = root.path + "/o.png";
  ProcessResult r = Render(test::CorpusPath("valid/2CylinderEngine/glTF-Binary/2CylinderEngine.glb"), out,
                           {"--max-memory", "8M"});
  EXPECT_TRUE(RefusedQuickly(r, out, {"2CylinderEngine.glb: ", "more than --max-memory 8 MiB allows"}));
  ProcessResult ok = Render(test::CorpusPath("valid/2CylinderEngine/glTF-Binary/2CylinderEngine.glb"), out,
                            {"--max-memory", "200M", "-v"});
  EXPECT_TRUE(ok.ExitedWith(0)) << ok.Describe();
  EXPECT_NE(ok.out.find("of --max-memory 200 MiB"), std::string::npos) << ok.out;
}

// --diff reads two images the same way: regular files only, pixels allocated only once
// the file has shown it holds them.
TEST(Amplification, DiffImagesAreCheckedBeforeAllocation) {
  TempDir root;
  const std::string fifo = root.path + "/a.pfm", huge = root.path + "/b.pfm", out = root.path + "/o.png";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  WriteFile(huge, "PF\n65536 65536\n-1.0\n" + std::string(64, '\0'));
  EXPECT_TRUE(RefusedQuickly(RunVkpt({"--diff", fifo, huge, "--out", out}), out, {fifo + ": is a FIFO"}));
  ProcessResult r = RunVkpt({"--diff", huge, huge, "--out", out});
  EXPECT_TRUE(RefusedQuickly(r, out, {huge + ": PFM data is truncated (65536x65536 needs 51539607552 bytes"}));
  EXPECT_LT(r.peakRssKiB, kSmallProcessKiB);
}

// JSON that is deep, or long, must cost linear time: a parser callback that rescans
// arrays took 36 s for 300,000 nodes (quadratic); the bound is far above the ~3 s a
// linear load of this file takes on a slow machine, and far below the quadratic time
// (both ×kTimeScale in sanitizer builds, where the linear load takes ~15 s).
TEST(Amplification, DeepOrLongJsonLoadsInLinearTime) {
  TempDir root;
  const std::string deep = root.path + "/deep.gltf", wide = root.path + "/wide.gltf", out = root.path + "/o.png";
  WriteFile(deep, R"({"asset":{"version":"2.0"},"extras":{"s":"[[[[[[[[[[[[[[[[[[[[","a":)" + std::string(100000, '[') +
                      std::string(100000, ']') + "}}");
  EXPECT_TRUE(RefusedQuickly(Render(deep, out), out, {deep + ": JSON is nested deeper than 256 levels"}));
  std::string json = R"({"asset":{"version":"2.0"},"nodes":[)";
  for (int i = 0; i < 300000; ++i) json += (i ? "," : "") + std::string(R"({"translation":[1,2,3],"name":"n"})");
  WriteFile(wide, json + "]}");
  ProcessResult r = Render(wide, out);
  EXPECT_TRUE(r.ExitedWith(1)) << r.Describe();
  EXPECT_NE(r.err.find("no triangles"), std::string::npos) << r.err;
  EXPECT_LT(r.seconds, 15.0 * test::kTimeScale);
}

// ---------------------------------------------------------------------------------------
// Messages: short, and about the problem.

TEST(Messages, BadDataUriIsNotEchoed) {
  TempDir root;
  const std::string scene = root.path + "/datauri.gltf", out = root.path + "/o.png";
  // 1 MB of base64 whose decoded length disagrees with byteLength.
  WriteFile(scene, TriangleGltf("data:application/octet-stream;base64," + std::string(1 << 20, 'A')));
  ProcessResult r = Render(scene, out);
  EXPECT_TRUE(RefusedQuickly(r, out, {scene + ": "}));
  EXPECT_LT(r.err.size(), 400u) << r.err.substr(0, 400);
}

TEST(Messages, ByteSizesNeverReadAlikeWhenTheyDiffer) {
  EXPECT_EQ(FormatBytes(128u << 20), "128 MiB");
  EXPECT_EQ(FormatBytes((128u << 20) + 1024), "128.00 MiB (134,218,752 bytes)");
  EXPECT_EQ(FormatBytes(1536), "1.50 KiB");
  EXPECT_EQ(FormatBytes(1), "1 byte");
  EXPECT_EQ(ParseByteSize("8G"), uint64_t(8) << 30);
  EXPECT_EQ(ParseByteSize("512MiB"), uint64_t(512) << 20);
  EXPECT_EQ(ParseByteSize("100"), 100u);
  EXPECT_FALSE(ParseByteSize("12X"));
  EXPECT_FALSE(ParseByteSize("99999999999T"));
}

TEST(Messages, BufferFileOfTheWrongSizeIsNamed) {
  TempDir root;
  WriteFile(root.path + "/short.bin", TriangleBytes().substr(0, 24));
  const std::string scene = root.path + "/scene.gltf", out = root.path + "/o.png";
  WriteFile(scene, TriangleGltf("short.bin"));
  EXPECT_TRUE(RefusedQuickly(Render(scene, out), out,
                             {"buffers[0].uri \"short.bin\" holds 24 bytes, but buffers[0].byteLength says 36"}));
}

// Under `ulimit -v` with a --max-memory above it (by default the budget is half the
// limit, tests/test_frame_memory.cpp) an allocation fails before the budget is reached:
// the message says memory ran out, not that the file is broken. (ASan reserves terabytes of address space
// for its shadow memory, so an address-space limit cannot apply to its builds.)
TEST(Messages, ProcessMemoryLimitIsReportedAsMemory) {
#if defined(VKPT_ADDRESS_SANITIZER)
  GTEST_SKIP() << "an address-space limit does not work with AddressSanitizer";
#endif
  TempDir root;
  const std::string nodes = root.path + "/nodes.gltf", sparse = root.path + "/sparse.gltf";
  const std::string out = root.path + "/o.png";
  std::string json = R"({"asset":{"version":"2.0"},"nodes":[)";
  for (int i = 0; i < 150000; ++i) json += (i ? "," : "") + std::string(R"({"translation":[1,2,3],"name":"n"})");
  WriteFile(nodes, json + "]}");
  MakeSparseFile(sparse, "{", off_t(200) << 20);
  const test::ChildLimits limits{.addressSpace = uint64_t(150) << 20};
  ProcessResult parse =
      RunVkpt({"--scene", nodes, "--out", out, "--backend", "cpu", "--max-memory", "64G"}, 20.0, "", {}, limits);
  EXPECT_TRUE(RefusedQuickly(parse, out, {nodes + ": ran out of memory while loading"}, 10.0));
  ProcessResult read =
      RunVkpt({"--scene", sparse, "--out", out, "--backend", "cpu", "--max-memory", "64G"}, 20.0, "", {}, limits);
  EXPECT_TRUE(RefusedQuickly(read, out, {sparse + ": not enough memory to read the file (200 MiB)"}));
  EXPECT_EQ(parse.err.find("JSON"), std::string::npos);
}

TEST(Messages, EveryErrorIsOneShortLine) {
  const std::string longPath = "/nonexistent" + std::string(3000, 'x') + ".gltf";
  ProcessResult error = RunVkpt({"--scene", longPath, "--out", "/nonexistent/o.png"});
  ProcessResult usage = RunVkpt({"--scene", "x.gltf", "--spp", std::string(3000, '9')});
  EXPECT_TRUE(error.ExitedWith(1)) << error.Describe();
  EXPECT_TRUE(usage.ExitedWith(2)) << usage.Describe();
  for (const std::string& err : {error.err, usage.err}) {
    EXPECT_LT(err.size(), 500u) << err;
    EXPECT_EQ(err.find('\n'), err.size() - 1) << err;
  }
}

TEST(Messages, UsageErrorForABadMemorySize) {
  ProcessResult r = RunVkpt({"--scene", "x.gltf", "--max-memory", "lots"});
  EXPECT_TRUE(r.ExitedWith(2)) << r.Describe();
  EXPECT_NE(r.err.find("--max-memory expects a size"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace vkpt::internal

// Shared test helpers: running the vkpt binary as a subprocess, statistics for Monte
// Carlo tests, paths to the scenes and to the external test data.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cie_1931.h"
#include "image/image.h"
#include "render/render_scene.h"
#include "scene/scene.h"
#include "session/budget.h"
#include "session/render_session.h"

namespace vkpt::internal::test {

// Time limits inside tests are multiplied by this: 1, or 4 in a sanitizer build
// (VKPT_SANITIZE), where code runs several times slower.
#ifndef VKPT_TIME_SCALE
#define VKPT_TIME_SCALE 1
#endif
constexpr double kTimeScale = VKPT_TIME_SCALE;
// The longest statistical tests, whose correct estimators must pass, take this many
// times fewer samples in a sanitizer build: there they run the code for the sanitizers,
// and the plain build measures (their mutants keep their samples everywhere).
#ifndef VKPT_SAMPLE_DIVISOR
#define VKPT_SAMPLE_DIVISOR 1
#endif
constexpr uint32_t kSampleDivisor = VKPT_SAMPLE_DIVISOR;
// A mutant's rejection or a long statistic adds nothing under AddressSanitizer (the code
// it runs is run there by other tests) and costs several times its plain time: it skips.
#if defined(VKPT_ADDRESS_SANITIZER)
#define VKPT_SKIP_UNDER_ADDRESS_SANITIZER(why) GTEST_SKIP() << why << " under AddressSanitizer; the plain build runs it"
#else
#define VKPT_SKIP_UNDER_ADDRESS_SANITIZER(why) static_cast<void>(0)
#endif

std::string SourcePath(const std::string& relative);  // <repo>/relative

// The external test data: a folder holding gltf-corpus/, gltf-pbr/ (its environments/
// too) and gltf-ext/. It is $VKPT_TEST_DATA if that is set, else ../shared beside the
// checkout; "" when that folder does not exist. A test that reads it begins with
// VKPT_REQUIRE_SHARED_DATA(): without the folder the test skips with one line saying how
// to get it (or fails, if $VKPT_REQUIRE_TEST_DATA is set, as CI sets it). With the folder,
// a file missing from it fails the test that reads it, as any missing input does.
std::string SharedDataDir();
std::string SharedData(const std::string& relative);  // SharedDataDir()/relative
std::string CorpusPath(const std::string& relative);  // SharedData("gltf-corpus/" + relative)
std::string SharedDataMissing();                      // the line a test skips (or fails) with
bool SharedDataRequired();                            // $VKPT_REQUIRE_TEST_DATA is set
// A macro, not a function: GTEST_SKIP() and FAIL() end the test by returning from it.
#define VKPT_REQUIRE_SHARED_DATA()                                                                           \
  do {                                                                                                       \
    if (!::vkpt::internal::test::SharedDataDir().empty()) break;                                             \
    if (::vkpt::internal::test::SharedDataRequired()) FAIL() << ::vkpt::internal::test::SharedDataMissing(); \
    GTEST_SKIP() << ::vkpt::internal::test::SharedDataMissing();                                             \
  } while (0)
// The CIE 1931 matching functions (scripts/cie_1931.h) as `cmf`, or the test skips
// naming the missing file. A macro for the same reason.
#define VKPT_REQUIRE_CMF(cmf)                                              \
  const ::vkpt::internal::cie::Cmf cmf = ::vkpt::internal::cie::LoadCmf(); \
  if (cmf.x.empty()) GTEST_SKIP() << ::vkpt::internal::cie::kCmfPath << " is missing (Debian's colord-data)"
std::string TempPath(const std::string& name);        // unique per test process
std::string FreshTempDirectory(const std::string& name);           // TempPath(name), created empty
std::vector<std::string> DirectoryListing(const std::string& dir);  // entry names, sorted

// A fresh folder (FreshTempDirectory) holding only what a test's run writes there,
// removed with everything in it at the end of the scope.
struct TempFolder {
  explicit TempFolder(const std::string& name);
  ~TempFolder();
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  std::string operator/(const std::string& file) const { return path + "/" + file; }
  std::vector<std::string> Listing() const { return DirectoryListing(path); }
  std::string path;
};
std::string ReadFile(const std::string& path);                      // every byte

struct ProcessResult {
  int exitCode = -1;     // valid when !signaled && !timedOut
  int signal = 0;        // the terminating signal, if any
  bool timedOut = false;
  double seconds = 0.0;  // wall time from start to exit
  double sentAt = -1.0;  // ChildSignals: seconds from start to the last signal sent (-1: none)
  long peakRssKiB = 0;   // the child's peak resident memory
  std::string out, err;
  bool ExitedWith(int code) const { return !timedOut && signal == 0 && exitCode == code; }
  std::string Describe() const;  // for failure messages
};

// Resource limits for the child, in bytes.
struct ChildLimits {
  // RLIMIT_FSIZE (`ulimit -f`): file writes fail past it, as they would on a full disk.
  std::optional<uint64_t> fileSize{};  // {}: designated initializers may leave either out
  // RLIMIT_AS (`ulimit -v`): allocations fail past it, as when memory runs out.
  std::optional<uint64_t> addressSpace{};
};

// Signals for the child: `delaySeconds` after its stdout first contains `after`, each of
// `signals` is sent in turn, `gapSeconds` apart; `sentAt` in the result is when the last
// one went.
struct ChildSignals {
  std::string after;
  std::vector<int> signals;
  double gapSeconds = 0.0;
  double delaySeconds = 0.0;
};

// Runs `build/vkpt args...`, killing it after timeoutSeconds × kTimeScale. A non-empty
// `cwd` is the child's working directory (for relative paths and the default output
// name); `env` entries ("NAME=value") are set in the child's environment.
ProcessResult RunVkpt(const std::vector<std::string>& args, double timeoutSeconds = 120.0, const std::string& cwd = "",
                      const std::vector<std::string>& env = {}, const ChildLimits& limits = {},
                      const ChildSignals& signals = {});

// The same for any program, by its path (mpirun, for the MPI tests).
ProcessResult RunProgram(const std::string& program, const std::vector<std::string>& args,
                         double timeoutSeconds = 120.0, const std::string& cwd = "",
                         const std::vector<std::string>& env = {}, const ChildLimits& limits = {},
                         const ChildSignals& signals = {});

// Statistics.
double ChiSquareSurvival(double statistic, double dof);  // P(X >= statistic), X ~ χ²(dof)
double NormalSurvivalTwoSided(double z);                 // P(|Z| >= z)
double SidakAlpha(double familyAlpha, int tests);        // per-test α for a family of tests

// Pearson χ² test of observed counts against expected counts. Cells with expected
// count < 5 are pooled (in order) so the χ² approximation holds. Returns the p-value
// and fills the statistic and degrees of freedom.
double ChiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected, double* statistic,
                     int* dof);

// A random triangle soup with the cases that break naive builders and intersectors:
// zero-area, collinear, huge, tiny and duplicated triangles.
std::vector<SceneTriangle> RandomSoup(uint32_t count, uint32_t seed);

// Monte Carlo image mean against an expected value.
struct ZTest {
  glm::dvec3 mean, stderr_, z;
};
// Image mean and its standard error from the per-pixel variances of the mean.
ZTest MeanAndError(const Image& img, glm::dvec3 expected);
// Prints the per-channel figures; true when every channel agrees (|z| < 3.2, or within
// the relative margin).
bool Agrees(const ZTest& t, glm::dvec3 expected, double margin, const char* what);
// Radiance in the furnace scene with paths capped at maxDepth bounces.
glm::dvec3 FurnaceExpected(const Scene& furnace, int maxDepth);

// A scene built in code (tests that need geometry no file has).
Scene MakeScene(const std::vector<SceneTriangle>& triangles, const std::vector<Material>& materials);

// Glass that light crosses straight at normal incidence: transmission 1 with a volume
// (KHR_materials_volume), no specular reflection (F = 0), a near-mirror roughness.
Material ClearGlass(glm::vec3 tint, glm::vec3 attenuation, float ior);
// A sphere of radius 1 about the origin of `material`, flat-shaded (geometric normals
// only, so that a BSDF keeps its energy exactly at every facet: 64 × 32
// latitude-longitude quads, wound to face out), in a white furnace (background 1), seen
// whole by an orthographic camera; and the parameters of its render: 48² pixels, 1024
// samples (divided by kSampleDivisor), paths ended by roulette alone (after 16 bounces),
// as light trapped by total internal reflection needs hundreds of bounces.
Scene SphereInFurnace(const Material& material);
shader::FrameParams SphereFurnaceParams(const RenderScene& rs, const Scene& s, uint32_t seed);
// An orthographic camera at (0, 0, z) looking along −z, framing [−half, half]².
Camera OrthographicAlongMinusZ(float z, float half);
// The slab [−3, 3]² × [−1, 1] of `material`, seen by an orthographic camera along −z that
// frames [−1.5, 1.5]²: every camera ray crosses it along z, a length of 2, and no ray
// grazes an edge.
Scene GlassSlabScene(const Material& material);
// The square [−1, 1]² in the plane z = 0 (two triangles facing +z) with vertex colours
// ColorAt(x, y), material `baseColor`, seen by an orthographic camera along −z that frames
// exactly the square: every camera ray hits it, and nothing but the background lies above it.
Scene VertexColorQuadScene(glm::vec3 baseColor);
glm::vec4 VertexColorQuadColorAt(float x, float y);  // linear in x and y
// Pixels of a render of VertexColorQuadScene (any spp, rrDepth ≥ 1, background B, no
// lights) off their exact bound: every sample is baseColor · ColorAt(hit) · B, so a pixel
// lies within the colour's range over the pixel's footprint (plus float rounding).
int PixelsOffVertexColorQuad(const Image& image, const shader::FrameParams& params, glm::vec3 baseColor);

// The square [−1, 1]² at z = 0, unlit (KHR_materials_unlit: every camera ray returns its
// base colour), textured by a 4 × 4 texture of 16 different sRGB colours (TexturedQuadTexel)
// with NEAREST filters and CLAMP_TO_EDGE: texel (0, 0) at the top left (−1, 1). Seen by
// an orthographic camera framing it exactly.
Scene TexturedQuadScene();
glm::u8vec4 TexturedQuadTexel(int x, int y);
// Pixels of a render of TexturedQuadScene (width and height multiples of 4, background 0)
// other than the decoded texel under them, bit for bit: a pixel's footprint lies inside one
// texel, so each of its samples returns that texel's value.
int PixelsOffTexturedQuad(const Image& image);

// A render of the scene's first camera at size × size: `spp` samples from seed `seed`,
// paths of at most `depth` bounces with no Russian roulette, background 0.
shader::FrameParams TestFrame(const RenderScene& rs, const Scene& s, uint32_t size, uint32_t spp, uint32_t seed,
                              uint32_t depth);

// A texture of `image` sampled as shader::Texture `mode` bits (wrap modes, filters) say,
// its RGB colour (sRGB) or data: the inverse of PackSampler, for tests that name samplers
// as the shaders see them.
SceneTexture TextureWithMode(uint32_t image, uint32_t mode, bool srgb = false);

// A RenderScene with the textures of `s` (TextureStore) and nothing else: what
// shared/texture.h's lookups read.
RenderScene TexturesOnly(const Scene& s);

// A Radiance (.hdr) file of w × h texels (w from 8 to 32767, so that stb reads it run-length
// encoded), each scanline channel coded in runs and literal dumps: texel (x, y) is
// RleHdrTexel(x, y) exactly. Every 64th texel of the first row is 2048 (a sun).
std::string RleHdr(int width, int height);
glm::vec3 RleHdrTexel(int x, int y);

// How many pixels of `image` are within `tolerance` (relative) of `expected` in every channel.
int PixelsNear(const Image& image, glm::vec3 expected, float tolerance);

// A render session of `frame` in passes under `budget` (session/local_passes.h), as vkpt
// renders one process's frame.
RenderedFrame RenderUnderBudget(FrameRenderer& frame, const RenderBudget& budget);

}  // namespace vkpt::internal::test

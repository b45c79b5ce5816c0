#include "test_util.h"

#include "session/local_passes.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

#include "render/texture_store.h"
#include "shared/estimator.h"

namespace vkpt::internal::test {

std::string SourcePath(const std::string& relative) { return std::string(VKPT_SOURCE_DIR) + "/" + relative; }

std::string SharedDataDir() {
  const char* env = std::getenv("VKPT_TEST_DATA");
  const std::string dir = env && *env ? std::string(env) : SourcePath("../shared");
  std::error_code ec;
  return std::filesystem::is_directory(dir, ec) ? dir : "";
}

std::string SharedData(const std::string& relative) {
  const std::string dir = SharedDataDir();
  return (dir.empty() ? std::string("<no test data>") : dir) + "/" + relative;
}

std::string CorpusPath(const std::string& relative) { return SharedData("gltf-corpus/" + relative); }

std::string SharedDataMissing() {
  const char* env = std::getenv("VKPT_TEST_DATA");
  const std::string where = env && *env ? "VKPT_TEST_DATA=" + std::string(env) + " is not a folder"
                                        : "no ../shared beside the checkout and VKPT_TEST_DATA is not set";
  return "needs the external test data (" + where +
         "): set VKPT_TEST_DATA to a folder holding gltf-corpus/, gltf-pbr/ and gltf-ext/, or put it at ../shared";
}

bool SharedDataRequired() {
  const char* env = std::getenv("VKPT_REQUIRE_TEST_DATA");
  return env && *env && std::string(env) != "0";
}
std::string TempPath(const std::string& name) {
  return "/tmp/vkpt-test-" + std::to_string(::getpid()) + "-" + name;
}

std::string FreshTempDirectory(const std::string& name) {
  const std::string dir = TempPath(name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directory(dir);
  return dir;
}

std::vector<std::string> DirectoryListing(const std::string& dir) {
  std::vector<std::string> names;
  for (const std::filesystem::directory_entry& e : std::filesystem::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string ProcessResult::Describe() const {
  std::string s = timedOut ? "timed out" : signal ? "killed by signal " + std::to_string(signal)
                                                  : "exit code " + std::to_string(exitCode);
  return s + "\nstdout: " + out.substr(0, 2000) + "\nstderr: " + err.substr(0, 2000);
}

TempFolder::TempFolder(const std::string& name) : path(FreshTempDirectory(name)) {}
TempFolder::~TempFolder() { std::filesystem::remove_all(path); }

ProcessResult RunVkpt(const std::vector<std::string>& args, double timeoutSeconds, const std::string& cwd,
                      const std::vector<std::string>& env, const ChildLimits& limits, const ChildSignals& signals) {
  return RunProgram(VKPT_BINARY, args, timeoutSeconds, cwd, env, limits, signals);
}

namespace {

// In the forked child: stdout and stderr to the pipes, stdin from /dev/null, the limits
// and environment set, then `program`.
[[noreturn]] void ExecChild(const std::string& program, const std::vector<std::string>& args, const std::string& cwd,
                            const std::vector<std::string>& env, const ChildLimits& limits, int outPipe[2],
                            int errPipe[2]) {
  dup2(outPipe[1], STDOUT_FILENO);
  dup2(errPipe[1], STDERR_FILENO);
  close(outPipe[0]);
  close(errPipe[0]);
  int devnull = open("/dev/null", O_RDONLY);
  dup2(devnull, STDIN_FILENO);
  if (!cwd.empty() && chdir(cwd.c_str()) != 0) _exit(126);
  for (const std::string& kv : env) putenv(const_cast<char*>(kv.c_str()));
  for (auto [resource, bytes] : {std::pair{RLIMIT_FSIZE, limits.fileSize}, {RLIMIT_AS, limits.addressSpace}}) {
    rlimit limit{bytes.value_or(RLIM_INFINITY), bytes.value_or(RLIM_INFINITY)};
    if (bytes && setrlimit(resource, &limit) != 0) _exit(126);
  }
  std::vector<char*> argv;
  std::string bin = program;
  argv.push_back(bin.data());
  std::vector<std::string> copy = args;
  for (std::string& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  execv(bin.c_str(), argv.data());
  _exit(127);
}

// Sends the child `signals` once its stdout shows signals.after: the first after
// delaySeconds, each next gapSeconds after the last.
class SignalSender {
 public:
  SignalSender(pid_t pid, const ChildSignals& signals, std::chrono::steady_clock::time_point start)
      : pid_(pid), signals_(signals), start_(start) {}

  bool Pending() const { return sent_ < signals_.signals.size(); }

  void Poll(ProcessResult& r) {
    if (!Pending() || r.out.find(signals_.after) == std::string::npos) return;
    const auto now = std::chrono::steady_clock::now();
    if (!triggered_) seen_ = now;
    triggered_ = true;
    if (std::chrono::duration<double>(now - seen_).count() < signals_.delaySeconds) return;
    if (sent_ > 0 && std::chrono::duration<double>(now - last_).count() < signals_.gapSeconds) return;
    kill(pid_, signals_.signals[sent_++]);
    last_ = now;
    r.sentAt = std::chrono::duration<double>(now - start_).count();
  }

 private:
  pid_t pid_;
  const ChildSignals& signals_;
  std::chrono::steady_clock::time_point start_, last_, seen_;
  size_t sent_ = 0;
  bool triggered_ = false;
};

// Reads the child's stdout and stderr into r until both close, or until the deadline,
// when it kills the child (r.timedOut).
void CollectOutput(pid_t pid, int out, int err, double timeoutSeconds, SignalSender& sender, ProcessResult& r) {
  auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds * kTimeScale);
  pollfd fds[2] = {{out, POLLIN, 0}, {err, POLLIN, 0}};
  std::string* sinks[2] = {&r.out, &r.err};
  int open = 2;
  while (open > 0) {
    sender.Poll(r);
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      kill(pid, SIGKILL);
      r.timedOut = true;
      break;
    }
    if (poll(fds, 2, int(std::min<long long>(left.count(), sender.Pending() ? 10 : 1000))) < 0) break;
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP))) continue;
      char buf[4096];
      ssize_t n = read(fds[i].fd, buf, sizeof buf);
      if (n > 0) {
        sinks[i]->append(buf, size_t(n));
      } else {
        close(fds[i].fd);
        fds[i].fd = -1;
        --open;
      }
    }
  }
  for (pollfd& f : fds)
    if (f.fd >= 0) close(f.fd);
}

}  // namespace

ProcessResult RunProgram(const std::string& program, const std::vector<std::string>& args, double timeoutSeconds,
                         const std::string& cwd, const std::vector<std::string>& env, const ChildLimits& limits,
                         const ChildSignals& signals) {
  ProcessResult r;
  int outPipe[2], errPipe[2];
  if (pipe(outPipe) != 0 || pipe(errPipe) != 0) {
    r.err = "pipe failed";
    return r;
  }
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = fork();
  if (pid == 0) ExecChild(program, args, cwd, env, limits, outPipe, errPipe);
  close(outPipe[1]);
  close(errPipe[1]);
  SignalSender sender(pid, signals, start);
  CollectOutput(pid, outPipe[0], errPipe[0], timeoutSeconds, sender, r);
  int status = 0;
  struct rusage usage {};
  wait4(pid, &status, 0, &usage);
  r.peakRssKiB = usage.ru_maxrss;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!r.timedOut) {
    if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
    else if (WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
  }
  return r;
}

namespace {

// Regularised lower incomplete gamma P(a, x): series for x < a + 1, Lentz's continued
// fraction for Q otherwise (Abramowitz & Stegun 6.5.29 and 6.5.31).
double RegularizedGammaQ(double a, double x) {
  if (x <= 0.0) return 1.0;
  const double lnPrefix = -x + a * std::log(x) - std::lgamma(a);
  if (x < a + 1.0) {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 100000 && std::abs(term) > std::abs(sum) * 1e-15; ++n) {
      term *= x / (a + n);
      sum += term;
    }
    return 1.0 - sum * std::exp(lnPrefix);
  }
  const double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 100000; ++i) {
    double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-15) break;
  }
  return std::exp(lnPrefix) * h;
}

}  // namespace

double ChiSquareSurvival(double statistic, double dof) { return RegularizedGammaQ(0.5 * dof, 0.5 * statistic); }

double NormalSurvivalTwoSided(double z) { return std::erfc(std::abs(z) / std::sqrt(2.0)); }

double SidakAlpha(double familyAlpha, int tests) { return 1.0 - std::pow(1.0 - familyAlpha, 1.0 / tests); }

double ChiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected, double* statistic,
                     int* dof) {
  double chi2 = 0.0, pooledObs = 0.0, pooledExp = 0.0;
  int cells = 0;
  for (size_t i = 0; i < expected.size(); ++i) {
    pooledObs += observed[i];
    pooledExp += expected[i];
    if (pooledExp >= 5.0) {
      chi2 += (pooledObs - pooledExp) * (pooledObs - pooledExp) / pooledExp;
      ++cells;
      pooledObs = pooledExp = 0.0;
    }
  }
  if (pooledExp > 0.0) {  // left-over small cells join the statistic as one more cell
    chi2 += (pooledObs - pooledExp) * (pooledObs - pooledExp) / pooledExp;
    ++cells;
  }
  *statistic = chi2;
  *dof = cells - 1;
  return ChiSquareSurvival(chi2, cells - 1);
}

// A random soup with the cases that break naive builders: zero-area triangles
// (repeated and collinear vertices), huge and tiny triangles, many identical triangles.
std::vector<SceneTriangle> RandomSoup(uint32_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  auto point = [&] { return glm::vec3(u(rng), u(rng), u(rng)) * 10.0f; };
  std::vector<SceneTriangle> tris;
  for (uint32_t i = 0; i < count; ++i) {
    glm::vec3 c = point();
    float size = std::pow(10.0f, u(rng) * 3.0f - 1.0f) * 0.1f;  // 1e-5 .. 10
    SceneTriangle t{c, c + glm::vec3(u(rng), u(rng), u(rng)) * size, c + glm::vec3(u(rng), u(rng), u(rng)) * size, 0};
    switch ((i + 7) % 23) {
      case 0: t.v1 = t.v0; break;                                  // repeated vertex
      case 1: t.v2 = t.v0 + 2.0f * (t.v1 - t.v0); break;            // collinear
      case 2: t.v1 = t.v2 = t.v0; break;                            // a point
      case 3: t.v1 = t.v0 + glm::vec3(40, 0, 0); t.v2 = t.v0 + glm::vec3(0, 40, 3); break;  // huge
      case 4: if (i > 23) t = tris[i - 23]; break;                  // duplicate
      case 5: t.v2 = t.v0 + (t.v1 - t.v0) * 0.37f; break;           // collinear after rounding
      default: break;
    }
    tris.push_back(t);
  }
  return tris;
}

// Image mean and its standard error from the per-pixel variances of the mean: pixels are
// independent, so Var(mean) = Σ Var(pixel mean) / N².
ZTest MeanAndError(const Image& img, glm::dvec3 expected) {
  glm::dvec3 sum(0.0), var(0.0);
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    sum += glm::dvec3(img.pixels[i]);
    var += glm::dvec3(img.variance[i]);
  }
  double n = double(img.pixels.size());
  ZTest t;
  t.mean = sum / n;
  t.stderr_ = glm::sqrt(var) / n;
  t.z = (t.mean - expected) / t.stderr_;
  return t;
}

// Passes when the difference is explained by noise (|z| below the Šidák-corrected critical
// value) or is within a relative margin too small to matter (float rounding in 1e6 paths).
bool Agrees(const ZTest& t, glm::dvec3 expected, double margin, const char* what) {
  // Two-sided α = 0.0014 per channel: family α = 1 − (1 − 0.0014)³ ≈ 0.004 (Šidák).
  const double zCrit = 3.2;
  bool ok = true;
  for (int c = 0; c < 3; ++c) {
    bool pass = std::abs(t.z[c]) < zCrit || std::abs(t.mean[c] - expected[c]) <= margin * expected[c];
    std::printf("%s channel %d: mean %.6f expected %.6f stderr %.2e z %.2f (|z| < %.1f or rel err <= %.0e) %s\n", what,
                c, t.mean[c], expected[c], t.stderr_[c], t.z[c], zCrit, margin, pass ? "ok" : "FAIL");
    ok &= pass;
  }
  return ok;
}

// A closed enclosure of albedo ρ and emission Le everywhere has radiance Le/(1−ρ); with
// paths capped at D bounces, Le(1−ρ^(D+1))/(1−ρ) (geometric series of the rendering
// equation's Neumann expansion L = E + KE + K²E + …).
glm::dvec3 FurnaceExpected(const Scene& s, int maxDepth) {
  glm::dvec3 rho(s.materials[0].baseColor), le(s.materials[0].emission);
  return le * (1.0 - glm::pow(rho, glm::dvec3(maxDepth + 1))) / (1.0 - rho);
}

Scene MakeScene(const std::vector<SceneTriangle>& triangles, const std::vector<Material>& materials) {
  Scene s;
  s.path = "(test scene)";
  s.triangles = triangles;
  s.materials = materials;
  // Appended, not `"m" + std::to_string(i)`: that trips GCC 12's false -Wrestrict (bug 105651).
  for (size_t i = 0; i < materials.size(); ++i) s.materialNames.push_back(std::string("m").append(std::to_string(i)));
  for (const SceneTriangle& t : triangles) {
    s.bounds.Extend(t.v0);
    s.bounds.Extend(t.v1);
    s.bounds.Extend(t.v2);
  }
  return s;
}

Material ClearGlass(glm::vec3 tint, glm::vec3 attenuation, float ior) {
  Material m{};
  m.baseColor = tint;
  m.specularColor = glm::vec3(1.0f);
  m.specular = 0.0f;
  m.ior = ior;
  m.transmission = 1.0f;
  m.attenuation = attenuation;
  m.volume = true;
  return m;
}

static std::vector<SceneTriangle> SphereTriangles() {
  const int nPhi = 64, nTheta = 32;
  auto at = [&](int i, int j) {
    const float phi = 2.0f * float(M_PI) * float(i % nPhi) / nPhi, theta = float(M_PI) * float(j) / nTheta;
    return glm::vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  };
  std::vector<SceneTriangle> tris;
  for (int j = 0; j < nTheta; ++j)
    for (int i = 0; i < nPhi; ++i) {
      const glm::vec3 a = at(i, j), b = at(i, j + 1), c = at(i + 1, j + 1), d = at(i + 1, j);
      if (j > 0) tris.push_back({a, b, d, 0});
      if (j + 1 < nTheta) tris.push_back({b, c, d, 0});
    }
  return tris;
}

Scene SphereInFurnace(const Material& material) {
  Scene s = MakeScene(SphereTriangles(), {material});
  s.cameras.push_back(OrthographicAlongMinusZ(3.0f, 0.7f));  // every pixel sees the sphere
  return s;
}

shader::FrameParams SphereFurnaceParams(const RenderScene& rs, const Scene& s, uint32_t seed) {
  shader::FrameParams p = MakeFrameParams(rs, s.cameras[0], 48, 48);
  p.seed = seed;
  p.sampleCount = 1024 / kSampleDivisor;
  p.maxDepth = 100000;
  p.rrDepth = 16;
  p.background = glm::vec3(1.0f);
  return p;
}

Camera OrthographicAlongMinusZ(float z, float half) {
  Camera cam;
  cam.name = "orthographic along -z";
  cam.position = glm::vec3(0.0f, 0.0f, z);
  cam.orthographic = true;
  cam.ymag = half;
  cam.xmag = half;
  return cam;
}

Scene GlassSlabScene(const Material& material) {
  std::vector<SceneTriangle> tris;
  glm::vec3 c[8];
  for (int i = 0; i < 8; ++i) c[i] = glm::vec3(i & 1 ? 3 : -3, i & 2 ? 3 : -3, i & 4 ? 1 : -1);
  // Counter-clockwise seen from outside: every face's winding faces out.
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    tris.push_back({c[f[0]], c[f[1]], c[f[2]], 0});
    tris.push_back({c[f[0]], c[f[2]], c[f[3]], 0});
  }
  Scene s = MakeScene(tris, {material});
  s.cameras.push_back(OrthographicAlongMinusZ(5.0f, 1.5f));
  return s;
}

glm::vec4 VertexColorQuadColorAt(float x, float y) { return {0.5f + 0.4f * x, 0.5f - 0.3f * y, 0.25f, 1.0f}; }

Scene VertexColorQuadScene(glm::vec3 baseColor) {
  Material m{};
  m.baseColor = baseColor;
  const glm::vec3 a(-1, -1, 0), b(1, -1, 0), c(1, 1, 0), d(-1, 1, 0);
  Scene s = MakeScene({{a, b, c, 0}, {a, c, d, 0}}, {m});
  auto colorAt = [](glm::vec3 p) { return VertexColorQuadColorAt(p.x, p.y); };
  for (const SceneTriangle& t : s.triangles) s.colors.push_back({colorAt(t.v0), colorAt(t.v1), colorAt(t.v2)});
  s.cameras.push_back(OrthographicAlongMinusZ(2.0f, 1.0f));
  return s;
}

int PixelsOffVertexColorQuad(const Image& image, const shader::FrameParams& params, glm::vec3 baseColor) {
  int off = 0;
  for (uint32_t py = 0; py < params.height; ++py)
    for (uint32_t px = 0; px < params.width; ++px) {
      // The colour is linear: over the pixel's footprint it spans the values at its corners.
      glm::vec3 lo(INFINITY), hi(-INFINITY);
      for (float jx : {0.0f, 1.0f})
        for (float jy : {0.0f, 1.0f}) {
          glm::vec3 o = shader::GenerateCameraRay(params, px, py, jx, jy).origin;
          glm::vec3 v = baseColor * glm::vec3(VertexColorQuadColorAt(o.x, o.y)) * params.background;
          lo = glm::min(lo, v);
          hi = glm::max(hi, v);
        }
      const glm::vec3 L = image.pixels[py * params.width + px];
      const float eps = 1e-4f;
      off += glm::any(glm::lessThan(L, lo - eps)) || glm::any(glm::greaterThan(L, hi + eps));
    }
  return off;
}

glm::u8vec4 TexturedQuadTexel(int x, int y) {
  return {uint8_t(16 + 60 * x), uint8_t(200 - 50 * y), uint8_t(37 * (x ^ y)), 255};
}

Scene TexturedQuadScene() {
  Material m{};
  m.baseColor = glm::vec3(1.0f);
  m.unlit = true;
  const glm::vec3 a(-1, -1, 0), b(1, -1, 0), c(1, 1, 0), d(-1, 1, 0);
  Scene s = MakeScene({{a, b, c, 0}, {a, c, d, 0}}, {m});
  // u from left to right, v from top to bottom (the image's rows).
  auto uv = [](glm::vec3 p) { return glm::vec2(0.5f * (p.x + 1.0f), 0.5f * (1.0f - p.y)); };
  for (const SceneTriangle& t : s.triangles) s.uvs.push_back({{uv(t.v0), uv(t.v1), uv(t.v2)}, {}});
  TextureImage im{"quad", 4, 4, {}};
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const glm::u8vec4 t = TexturedQuadTexel(x, y);
      im.rgba.insert(im.rgba.end(), {t.r, t.g, t.b, t.a});
    }
  s.images.push_back(im);
  s.textures.push_back(TextureWithMode(
      0,
      shader::kWrapClampToEdge << shader::kTextureWrapSShift | shader::kWrapClampToEdge << shader::kTextureWrapTShift,
      true));
  s.materials[0].texture(TextureSlot::kBaseColor).texture = 0;
  s.cameras.push_back(OrthographicAlongMinusZ(2.0f, 1.0f));
  return s;
}

int PixelsOffTexturedQuad(const Image& image) {
  const std::vector<float> table = TexelDecodeTable();
  int off = 0;
  for (uint32_t py = 0; py < image.height; ++py)
    for (uint32_t px = 0; px < image.width; ++px) {
      const glm::u8vec4 t = TexturedQuadTexel(int(px * 4 / image.width), int(py * 4 / image.height));
      off += image.pixels[py * image.width + px] != glm::vec3(table[t.r], table[t.g], table[t.b]);
    }
  return off;
}

shader::FrameParams TestFrame(const RenderScene& rs, const Scene& s, uint32_t size, uint32_t spp, uint32_t seed,
                              uint32_t depth) {
  shader::FrameParams p = MakeFrameParams(rs, s.cameras[0], size, size);
  p.seed = seed;
  p.sampleCount = spp;
  p.maxDepth = depth;
  p.rrDepth = depth;
  return p;
}

SceneTexture TextureWithMode(uint32_t image, uint32_t mode, bool srgb) {
  using Wrap = TextureSampler::Wrap;
  const Wrap wraps[3] = {Wrap::kRepeat, Wrap::kClampToEdge, Wrap::kMirroredRepeat};
  SceneTexture t;
  t.image = image;
  t.sampler.wrapS = wraps[(mode >> shader::kTextureWrapSShift) & 3u];
  t.sampler.wrapT = wraps[(mode >> shader::kTextureWrapTShift) & 3u];
  t.sampler.magLinear = (mode & shader::kTextureMagLinear) != 0u;
  t.sampler.minLinear = (mode & shader::kTextureMinLinear) != 0u;
  t.sampler.mip = (mode & shader::kTextureMipNearest)  ? TextureSampler::Mip::kNearest
                  : (mode & shader::kTextureMipLinear) ? TextureSampler::Mip::kLinear
                                                       : TextureSampler::Mip::kNone;
  t.srgb = srgb;
  EXPECT_EQ(PackSampler(t), mode) << "not a sampler's mode bits";
  return t;
}

RenderScene TexturesOnly(const Scene& s) {
  TextureStore store = BuildTextureStore(s, 0);
  RenderScene rs;
  rs.textures = std::move(store.textures);
  rs.texels = std::move(store.words);
  rs.texelDecode = TexelDecodeTable();
  return rs;
}

int PixelsNear(const Image& image, glm::vec3 expected, float tolerance) {
  int n = 0;
  for (const glm::vec3& px : image.pixels)
    n += glm::all(glm::lessThanEqual(glm::abs(px - expected), tolerance * expected));
  return n;
}

RenderedFrame RenderUnderBudget(FrameRenderer& frame, const RenderBudget& budget) {
  LocalPasses source(frame, budget.chunkSpp);
  SessionSettings settings;
  settings.budget = budget;
  return RenderSession(source, settings);
}

namespace {

// RLE-HDR texel (x, y) as RGBE bytes: runs of 8 in red, a literal ramp in green, blue
// constant, the exponent changing by row; the sun a bright texel in the first row.
std::array<uint8_t, 4> RleHdrRgbe(int x, int y) {
  if (y == 0 && x % 64 == 0) return {128, 128, 128, 128 + 12};  // 0.5 · 2^12 = 2048
  return {uint8_t(64 + (x / 8 % 4) * 32), uint8_t(128 + (x * 7 + y * 13) % 128), 128, uint8_t(129 + y % 3)};
}

}  // namespace

glm::vec3 RleHdrTexel(int x, int y) {
  const std::array<uint8_t, 4> c = RleHdrRgbe(x, y);
  const float scale = std::ldexp(1.0f, int(c[3]) - 136);  // stb: mantissa · 2^(e − 128 − 8)
  return glm::vec3(c[0], c[1], c[2]) * scale;
}

std::string RleHdr(int width, int height) {
  std::string s =
      "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(height) + " +X " + std::to_string(width) + "\n";
  std::vector<uint8_t> v(static_cast<size_t>(width));
  for (int y = 0; y < height; ++y) {
    s += {char(2), char(2), char(width >> 8), char(width & 0xff)};
    for (int k = 0; k < 4; ++k) {
      for (int x = 0; x < width; ++x) v[x] = RleHdrRgbe(x, y)[k];
      auto runAt = [&](int i) {
        int r = 1;
        while (i + r < width && r < 127 && v[i + r] == v[i]) ++r;
        return r;
      };
      for (int i = 0; i < width;) {
        if (const int r = runAt(i); r >= 3) {
          s += {char(128 + r), char(v[i])};
          i += r;
          continue;
        }
        int j = i;
        while (j < width && j - i < 128 && runAt(j) < 3) ++j;
        s += char(j - i);
        for (int t = i; t < j; ++t) s += char(v[t]);
        i = j;
      }
    }
  }
  return s;
}

}  // namespace vkpt::internal::test

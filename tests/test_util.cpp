#include "test_util.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstring>

namespace vkpt::test {

std::string SourcePath(const std::string& relative) { return std::string(VKPT_SOURCE_DIR) + "/" + relative; }
std::string CorpusPath(const std::string& relative) { return std::string(VKPT_CORPUS_DIR) + "/" + relative; }
std::string TempPath(const std::string& name) {
  return "/tmp/vkpt-test-" + std::to_string(::getpid()) + "-" + name;
}

std::string ProcessResult::Describe() const {
  std::string s = timedOut ? "timed out" : signal ? "killed by signal " + std::to_string(signal)
                                                  : "exit code " + std::to_string(exitCode);
  return s + "\nstdout: " + out.substr(0, 2000) + "\nstderr: " + err.substr(0, 2000);
}

ProcessResult RunVkpt(const std::vector<std::string>& args, double timeoutSeconds, const std::string& cwd) {
  ProcessResult r;
  int outPipe[2], errPipe[2];
  if (pipe(outPipe) != 0 || pipe(errPipe) != 0) {
    r.err = "pipe failed";
    return r;
  }
  pid_t pid = fork();
  if (pid == 0) {
    dup2(outPipe[1], STDOUT_FILENO);
    dup2(errPipe[1], STDERR_FILENO);
    close(outPipe[0]);
    close(errPipe[0]);
    int devnull = open("/dev/null", O_RDONLY);
    dup2(devnull, STDIN_FILENO);
    if (!cwd.empty() && chdir(cwd.c_str()) != 0) _exit(126);
    std::vector<char*> argv;
    std::string bin = VKPT_BINARY;
    argv.push_back(bin.data());
    std::vector<std::string> copy = args;
    for (std::string& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(bin.c_str(), argv.data());
    _exit(127);
  }
  close(outPipe[1]);
  close(errPipe[1]);
  auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
  pollfd fds[2] = {{outPipe[0], POLLIN, 0}, {errPipe[0], POLLIN, 0}};
  std::string* sinks[2] = {&r.out, &r.err};
  int open = 2;
  while (open > 0) {
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      kill(pid, SIGKILL);
      r.timedOut = true;
      break;
    }
    if (poll(fds, 2, int(std::min<long long>(left.count(), 1000))) < 0) break;
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
  int status = 0;
  waitpid(pid, &status, 0);
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

Scene MakeScene(const std::vector<SceneTriangle>& triangles, const std::vector<Material>& materials) {
  Scene s;
  s.path = "(test scene)";
  s.triangles = triangles;
  s.materials = materials;
  for (size_t i = 0; i < materials.size(); ++i) s.materialNames.push_back("m" + std::to_string(i));
  for (const SceneTriangle& t : triangles) {
    s.bounds.Extend(t.v0);
    s.bounds.Extend(t.v1);
    s.bounds.Extend(t.v2);
  }
  return s;
}

}  // namespace vkpt::test

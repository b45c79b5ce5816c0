#include "x_server.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

#include "test_util.h"

namespace vkpt::internal::test {
namespace {

namespace fs = std::filesystem;

// The program's path on PATH, or "".
std::string Which(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/" + program;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

// `timeout 10 program args...`, its output kept (RunProgram kills it after 15 s too).
ProcessResult RunBounded(const std::string& program, const std::vector<std::string>& args) {
  std::vector<std::string> all = {"10", program};
  all.insert(all.end(), args.begin(), args.end());
  return RunProgram(Which("timeout"), all, 15.0);
}

std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Waits at most `seconds` for a line on `fd` (Xvfb's -displayfd): true when one came,
// false on end of file or time out (`timedOut` says which).
bool ReadyLine(int fd, double seconds, bool& timedOut) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  std::string got;
  timedOut = false;
  while (got.find('\n') == std::string::npos) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return !(timedOut = true);
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, int(left.count())) <= 0) continue;
    char buf[64];
    const ssize_t n = read(fd, buf, sizeof buf);
    if (n <= 0) return false;
    got.append(buf, size_t(n));
  }
  return true;
}

}  // namespace

ScopedEnv::ScopedEnv(const std::string& name, const std::optional<std::string>& value) : name_(name) {
  if (const char* old = std::getenv(name.c_str())) old_ = old;
  if (value) setenv(name.c_str(), value->c_str(), 1);
  else unsetenv(name.c_str());
}

ScopedEnv::~ScopedEnv() {
  if (old_) setenv(name_.c_str(), old_->c_str(), 1);
  else unsetenv(name_.c_str());
}

XServer::XServer(uint32_t width, uint32_t height) {
  std::string missing;
  for (const char* tool : {"Xvfb", "xwininfo", "import", "xdotool", "timeout"})
    if (Which(tool).empty()) missing += std::string(missing.empty() ? "" : ", ") + tool;
  if (!missing.empty()) {
    skipped_ = "no " + missing + " for the window tests (apt-get install xvfb x11-utils imagemagick xdotool)";
    return;
  }
  if (!Start(width, height)) return;
  display_.emplace("DISPLAY", Display());
  wayland_.emplace("WAYLAND_DISPLAY", std::nullopt);
}

// One Xvfb per try: a number whose socket and lock file are absent may still be taken by
// a process racing for it, when Xvfb exits without writing to -displayfd: then the next.
bool XServer::Start(uint32_t width, uint32_t height) {
  const std::string screen = std::to_string(width) + "x" + std::to_string(height) + "x24";
  for (int n = 90, tries = 0; n < 190 && tries < 10; ++n) {
    const std::string x = std::to_string(n);
    if (fs::exists("/tmp/.X11-unix/X" + x) || fs::exists("/tmp/.X" + x + "-lock")) continue;
    ++tries;
    const std::string log = (fs::temp_directory_path() / ("vkpt-xvfb-" + std::to_string(getpid()) + "-" + x + ".log"));
    int ready[2];
    if (pipe2(ready, O_CLOEXEC) != 0) {
      error_ = "pipe2 failed";
      return false;
    }
    // Everything the child needs is made before fork(): after it, in a process with
    // threads, the child may only make system calls until exec.
    const std::string program = Which("Xvfb"), display = ":" + x, fd = std::to_string(ready[1]);
    const pid_t pid = fork();
    if (pid == 0) {
      fcntl(ready[1], F_SETFD, 0);  // the one descriptor Xvfb inherits
      const int null = open("/dev/null", O_RDWR), out = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      dup2(null, STDIN_FILENO), dup2(out, STDOUT_FILENO), dup2(out, STDERR_FILENO);
      execl(program.c_str(), "Xvfb", display.c_str(), "-screen", "0", screen.c_str(), "-nolisten", "tcp", "-displayfd",
            fd.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    close(ready[1]);
    bool timedOut = false;
    const bool up = pid > 0 && ReadyLine(ready[0], 10.0 * kTimeScale, timedOut);
    close(ready[0]);
    if (up) {
      pid_ = pid, number_ = n;
      fs::remove(log);
      return true;
    }
    if (pid > 0) {
      if (timedOut) kill(pid, SIGKILL);
      waitpid(pid, nullptr, 0);
    }
    error_ = "Xvfb :" + x + (timedOut ? " accepted no connection within 10 s: " : " exited: ") + ReadText(log);
    fs::remove(log);
    if (timedOut) return false;
  }
  if (error_.empty()) error_ = "no free X display number from :90 to :189";
  return false;
}

XServer::~XServer() {
  wayland_.reset();
  display_.reset();
  if (pid_ <= 0) return;
  kill(pid_, SIGTERM);
  for (int i = 0; i < 100; ++i) {
    if (waitpid(pid_, nullptr, WNOHANG) == pid_) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  kill(pid_, SIGKILL);
  waitpid(pid_, nullptr, 0);
}

std::optional<WindowGeometry> XServer::FindWindow(const std::string& title) const {
  if (!Running()) return std::nullopt;
  const ProcessResult r = RunBounded("xwininfo", {"-display", Display(), "-name", title});
  if (!r.ExitedWith(0)) return std::nullopt;
  const auto field = [&](const std::string& name) -> std::optional<long long> {
    std::smatch m;
    if (!std::regex_search(r.out, m, std::regex(name + R"(:\s+(0x[0-9a-fA-F]+|-?[0-9]+))"))) return std::nullopt;
    return std::stoll(m[1].str(), nullptr, 0);
  };
  const auto id = field("Window id"), x = field("Absolute upper-left X"), y = field("Absolute upper-left Y");
  const auto w = field("Width"), h = field("Height");
  if (!id || !x || !y || !w || !h) return std::nullopt;
  return WindowGeometry{uint64_t(*id), int(*x), int(*y), uint32_t(*w), uint32_t(*h)};
}

std::vector<uint8_t> XServer::ReadWindowRGB(const std::string& title, uint32_t& width, uint32_t& height) const {
  width = height = 0;
  const std::optional<WindowGeometry> g = FindWindow(title);
  if (!g) return {};
  const std::string crop = std::to_string(g->width) + "x" + std::to_string(g->height) + "+" + std::to_string(g->x) +
                           "+" + std::to_string(g->y);
  const ProcessResult r =
      RunBounded("import", {"-display", Display(), "-window", "root", "-crop", crop, "-depth", "8", "rgb:-"});
  if (!r.ExitedWith(0) || r.out.size() != size_t(g->width) * g->height * 3) return {};
  width = g->width, height = g->height;
  return std::vector<uint8_t>(r.out.begin(), r.out.end());
}

bool XServer::Xdotool(const std::vector<std::string>& args) const {
  return Running() && RunBounded("xdotool", args).ExitedWith(0);
}

bool XServer::SendKeys(const std::string& title, const std::vector<std::string>& keys, const std::string& verb) const {
  const std::optional<WindowGeometry> g = FindWindow(title);
  if (!g) return false;
  std::vector<std::string> args = {"mousemove", "--window", std::to_string(g->id), "40", "40", "sleep", "0.05", verb};
  args.insert(args.end(), keys.begin(), keys.end());
  return Xdotool(args);
}

bool XServer::MouseDrag(const std::string& title, int x0, int y0, int x1, int y1, int steps) const {
  const std::optional<WindowGeometry> g = FindWindow(title);
  if (!g) return false;
  const std::string id = std::to_string(g->id);
  std::vector<std::string> args = {"mousemove", "--window",  id, std::to_string(x0), std::to_string(y0), "sleep",
                                   "0.05",      "mousedown", "1"};
  for (int i = 1; i <= steps + 1; ++i) {
    const int x = x0 + (x1 - x0) * i / (steps + 1), y = y0 + (y1 - y0) * i / (steps + 1);
    args.insert(args.end(), {"sleep", "0.05", "mousemove", "--window", id, std::to_string(x), std::to_string(y)});
  }
  args.insert(args.end(), {"sleep", "0.05", "mouseup", "1"});
  return Xdotool(args);
}

bool XServer::MouseClick(const std::string& title, int x, int y) const {
  const std::optional<WindowGeometry> g = FindWindow(title);
  if (!g) return false;
  return Xdotool({"mousemove", "--window", std::to_string(g->id), std::to_string(x), std::to_string(y), "sleep", "0.3",
                  "click", "1"});
}

}  // namespace vkpt::internal::test

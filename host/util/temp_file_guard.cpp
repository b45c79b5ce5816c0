#include "util/temp_file_guard.h"

#include <limits.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "util/error.h"
#include "util/graceful_stop.h"

namespace vkpt::internal {
namespace {

// What the handler removes. A fixed buffer: a signal handler may not allocate, and the
// guard's own std::string is out of its reach.
char gPath[PATH_MAX];
volatile sig_atomic_t gActive = 0;

// Async-signal-safe: unlink(2) and raise(3) only. SA_RESETHAND has already restored the
// default action, so the re-raised signal (pending until the handler returns) ends the
// process as the signal would have: the parent sees death by SIGINT/SIGTERM (130/143).
extern "C" void UnlinkAndReraise(int sig) {
  ::unlink(gPath);
  ::raise(sig);
}

// A signal that is ignored (nohup, a background job of a non-interactive shell) cannot
// interrupt the write, and must stay ignored: no handler for it.
void Install(int sig, struct sigaction* old) {
  ::sigaction(sig, nullptr, old);
  if (old->sa_handler == SIG_IGN || GracefulStop::Active()) return;
  struct sigaction sa{};
  sa.sa_handler = UnlinkAndReraise;
  sa.sa_flags = SA_RESETHAND;
  // SIGINT and SIGTERM together: the handler is not itself interrupted by the other.
  ::sigemptyset(&sa.sa_mask);
  ::sigaddset(&sa.sa_mask, SIGINT);
  ::sigaddset(&sa.sa_mask, SIGTERM);
  ::sigaction(sig, &sa, nullptr);
}

}  // namespace

TempFileGuard::TempFileGuard(const std::string& path) : path_(path) {
  if (gActive) throw std::logic_error("TempFileGuard: a second guard while one is alive");
  // open(2) would refuse such a name too; refuse it before the handler could see half.
  if (path.size() >= sizeof gPath) throw Error(path + ": " + std::strerror(ENAMETOOLONG));
  std::memcpy(gPath, path.c_str(), path.size() + 1);
  gActive = 1;
  Install(SIGINT, &oldInt_);
  Install(SIGTERM, &oldTerm_);
}

TempFileGuard::~TempFileGuard() {
  // Unlink before restoring the actions: a signal in between finds the file gone, never
  // a file without a handler to remove it.
  if (!dismissed_) ::unlink(path_.c_str());
  ::sigaction(SIGTERM, &oldTerm_, nullptr);
  ::sigaction(SIGINT, &oldInt_, nullptr);
  gActive = 0;
}

void RemoveGuardedFileForSignal() {
  if (gActive) ::unlink(gPath);
}

}  // namespace vkpt::internal

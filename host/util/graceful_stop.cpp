#include "util/graceful_stop.h"

#include <signal.h>

#include <stdexcept>

#include "util/temp_file_guard.h"

namespace vkpt::internal {
namespace {

volatile sig_atomic_t gSignal = 0;
bool gActive = false;
struct sigaction gOldInt {
}, gOldTerm{};

// Async-signal-safe: records the first signal; on the second, unlink(2) (in
// RemoveGuardedFileForSignal), sigaction(2) and raise(3) only. The re-raised signal is
// blocked until the handler returns, then ends the process with the default action.
extern "C" void OnStopSignal(int sig) {
  if (gSignal == 0) {
    gSignal = sig;
    return;
  }
  RemoveGuardedFileForSignal();
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  ::sigaction(sig, &dfl, nullptr);
  ::raise(sig);
}

// A signal that is ignored (nohup, a background job of a non-interactive shell) stays
// ignored.
void Install(int sig, struct sigaction* old) {
  ::sigaction(sig, nullptr, old);
  if (old->sa_handler == SIG_IGN) return;
  struct sigaction sa {};
  sa.sa_handler = OnStopSignal;
  ::sigemptyset(&sa.sa_mask);  // SIGINT and SIGTERM together: one handler at a time
  ::sigaddset(&sa.sa_mask, SIGINT);
  ::sigaddset(&sa.sa_mask, SIGTERM);
  ::sigaction(sig, &sa, nullptr);
}

}  // namespace

GracefulStop::GracefulStop() {
  if (gActive) throw std::logic_error("GracefulStop: a second one while one is alive");
  gActive = true;
  gSignal = 0;
  Install(SIGINT, &gOldInt);
  Install(SIGTERM, &gOldTerm);
}

GracefulStop::~GracefulStop() {
  ::sigaction(SIGTERM, &gOldTerm, nullptr);
  ::sigaction(SIGINT, &gOldInt, nullptr);
  gActive = false;
}

int GracefulStop::Signal() { return gSignal; }
bool GracefulStop::Active() { return gActive; }

}  // namespace vkpt::internal

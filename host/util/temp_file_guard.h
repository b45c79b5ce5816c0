// Removes a temporary file unless it was dismissed: when the guard is destroyed (an
// error unwinding the stack) and when SIGINT or SIGTERM arrives while it is alive, so
// neither a failure nor an interrupted write leaves a partial file behind. While a
// GracefulStop is alive the signals are its own: the first lets the write finish, a
// second removes the file (RemoveGuardedFileForSignal) and ends the process.
#pragma once

#include <signal.h>

#include <string>

namespace vkpt::internal {

class TempFileGuard {
 public:
  // Takes charge of `path` (create the file after this, so no moment is unguarded).
  // One guard at a time: the signal handler has one static path to remove.
  explicit TempFileGuard(const std::string& path);
  ~TempFileGuard();  // unlinks the file unless dismissed; restores the signal actions
  TempFileGuard(const TempFileGuard&) = delete;
  TempFileGuard& operator=(const TempFileGuard&) = delete;

  // The file is no longer temporary (renamed to its final name): leave it alone.
  void Dismiss() { dismissed_ = true; }

 private:
  std::string path_;
  bool dismissed_ = false;
  struct sigaction oldInt_{}, oldTerm_{};
};

// From a signal handler: unlinks the file of the live guard, if any (async-signal-safe).
void RemoveGuardedFileForSignal();

}  // namespace vkpt::internal

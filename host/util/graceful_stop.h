// Ctrl-C during a long render keeps the work done: while a GracefulStop is alive, the
// first SIGINT or SIGTERM does not end vkpt but is recorded, so that the render loop can
// stop after its current pass and write what it has. A second one ends the process at
// once, as that signal would (a shell sees 130 or 143), after removing the temporary
// file of a TempFileGuard that is writing meanwhile.
#pragma once

namespace vkpt::internal {

class GracefulStop {
 public:
  GracefulStop();   // installs the handlers (one GracefulStop at a time)
  ~GracefulStop();  // restores the previous actions
  GracefulStop(const GracefulStop&) = delete;
  GracefulStop& operator=(const GracefulStop&) = delete;

  static int Signal();                             // the first signal received while one was alive, or 0
  static bool Arrived() { return Signal() != 0; }  // a render loop's stop: ends it between passes
  static bool Active();                            // whether one is alive (TempFileGuard then leaves signals to it)
};

}  // namespace vkpt::internal

// vkpt --interactive: the options as the viewer takes them (viewer/viewer.h), and the
// batch command that renders what the viewer shows.
#pragma once

#include <string>

#include "app/options.h"
#include "viewer/viewer.h"

namespace vkpt::internal {

// The command line of `o` that renders `frame` (viewer/viewer.h): its view, samples and
// size, and every setting the viewer changed, shell-quoted; every other option as given.
// Its render is the viewer's picture, bit for bit (same device).
std::string BatchCommand(const Options& o, const ViewedFrame& frame);

// Opens the window and runs the viewer; returns the exit status. Throws UsageError
// without a display (before loading anything) or without the viewer built, Error else.
int RunInteractive(const Options& o);

}  // namespace vkpt::internal

// vkpt --interactive: the options as the viewer takes them (viewer/viewer.h), and the
// batch command that renders what the viewer shows.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "app/options.h"

namespace vkpt::internal {

// The command line of `o` with the view `camera` (none: the options' own camera), at
// `spp` samples per pixel and `width` × `height`, shell-quoted: every other option as
// given. Its render is the viewer's picture at that spp, bit for bit (same device).
std::string BatchCommand(const Options& o, const std::optional<vkpt::Camera>& camera, uint32_t spp, uint32_t width,
                         uint32_t height);

// Opens the window and runs the viewer; returns the exit status. Throws UsageError
// without a display (before loading anything) or without the viewer built, Error else.
int RunInteractive(const Options& o);

}  // namespace vkpt::internal

// The caller's log (SceneOptions::log) fed by the engine and the session: warnings (what
// the file uses and vkpt ignores, a black image ahead, a fallback to the CPU, validation
// messages), notices, and the details the command line prints with -v; each message in
// the API's terms.
#pragma once

#include "vkpt/view.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal {

EngineLog EngineLogOf(const vkpt::LogCallback& log);

// A render's settings with its warnings and per-pass lines going to `log`.
ClientView LoggedView(const vkpt::LogCallback& log);

// What the load found worth a warning: the scene's warnings and ignored features.
void LogLoad(const vkpt::LogCallback& log, const Scene& scene);

}  // namespace vkpt::internal

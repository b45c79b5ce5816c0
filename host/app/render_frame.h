// One frame's render from prepared options, and what follows it: the session settings
// and hooks the options give, the render itself, the CPU reference of --compare, and the
// files, reports and stats written after it (Finish). Run, RunSequence and RunRank share
// these (app/run.cpp).
#pragma once

#include <string>

#include "app/options.h"
#include "app/prepare.h"
#include "session/backend.h"
#include "session/render_session.h"
#include "session/sample_source.h"

namespace vkpt {

SessionSettings SettingsFromOptions(const Options& o, const RenderBackend& backend);

// Renders `source` under `settings`, with the progress line and reports the options ask for.
RenderedFrame Render(SampleSource& source, const SessionSettings& settings, const Options& o);

// --compare's reference: the same samples on the CPU, without budgets but --spp.
RenderedFrame RenderReference(const Prepared& p, const Options& o);

// After the render: the files, the reports and the stats (into *frameStats for a frame of
// a sequence, else to --stats); the exit status.
int Finish(const Options& o, Prepared& p, const RenderedFrame& frame, const RenderedFrame* reference,
           const RenderBackend& backend, std::string* frameStats = nullptr);

}  // namespace vkpt

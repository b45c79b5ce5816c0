// What follows a frame's render on the command line: the CPU reference of --compare, and
// the files, reports and stats written after the render (Finish). Both ways of rendering
// a frame share these (app/run.cpp); the render itself is the library's
// (app/scene_client.h).
#pragma once

#include <string>

#include "app/options.h"
#include "app/prepare.h"
#include "session/render_session.h"

namespace vkpt::internal {

// --compare's reference: the begun frame's samples on the CPU, without budgets but --spp.
RenderedFrame RenderReference(Prepared& p, const Options& o);

// After the render: the files, the reports and the stats (into *frameStats for a frame of
// a sequence, else to --stats); the exit status.
int Finish(const Options& o, Prepared& p, const RenderedView& rendered, const RenderedFrame* reference,
           std::string* frameStats = nullptr);

}  // namespace vkpt::internal

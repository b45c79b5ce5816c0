// The command line as a client of the library: its options as the API's scene options,
// camera and render options (vkpt/vkpt.h), its scene opened and its frames rendered
// through a vkpt::Scene (vkpt/client.h).
#pragma once

#include <memory>

#include "app/options.h"
#include "session/sample_source.h"
#include "vkpt/view.h"

namespace vkpt::internal {

class SceneClient {
 public:
  // Opens o.scene as the options say; `log` receives the engine's warnings, notices and
  // -v lines about the load.
  SceneClient(const Options& o, const EngineLog& log);
  ~SceneClient();
  SceneClient(SceneClient&&) noexcept;
  SceneClient& operator=(SceneClient&&) noexcept;

  vkpt::Scene& Public();

  // The frame the options describe (their camera, size, --at), prepared and begun.
  BegunView Begin(const Options& o, const ClientView& client);
  // The render of the frame begun last from `source`, with the progress line and ended by
  // a signal.
  RenderedView Finish(BegunView& view, SampleSource& source, const ClientView& client);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// What the options ask of a frame beyond the API's render options: its output file (named
// in refusals, rewritten by checkpoints, its format counted), the ranks whose chunks this
// process collects, and where the frame's warnings and -v lines go (`log`; nothing for a
// process that does not report).
ClientView ClientViewOf(const Options& o, const EngineLog& log, uint32_t ranks);

}  // namespace vkpt::internal

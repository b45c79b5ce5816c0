// The library's door for a client inside vkpt, the command line: a vkpt::Scene opened
// with the settings the API does not offer, its views begun and finished in two steps (so
// that an MPI job's ranks can render a begun frame's chunks from their own source), and
// the engine under the scene for the client's reports. Scene::Render is BeginView, the
// local passes and FinishView, so the command line renders what the library renders.
// These leave errors in the engine's terms (the command line's); the public API's own
// functions translate them (Translated).
//
// Include this after every engine header: from here on vkpt::Scene, vkpt::Image, … name
// both the engine's types and the public ones (vkpt/vkpt.h).
#pragma once

#include <exception>
#include <new>
#include <string>

#include "vkpt/api_terms.h"
#include "vkpt/view.h"
#include "vkpt/vkpt.h"

namespace vkpt {

api::Scene OpenScene(const std::string& path, const api::SceneOptions& options, const ClientScene& client);
LoadedScene& EngineOf(api::Scene& scene);

BegunView BeginView(api::Scene& scene, const api::Camera& camera, const api::RenderOptions& options,
                    const ClientView& client);
// Renders a begun view from `source` (its frame's local passes, or an MPI job's dealt
// chunks), then its AOV pass and filter as the options ask.
RenderedView FinishView(api::Scene& scene, BegunView& view, SampleSource& source, const api::RenderOptions& options,
                        const ClientView& client);

// Any failure inside as the one public exception, its message in the API's terms.
template <class F>
auto Translated(F&& f) {
  try {
    return f();
  } catch (const api::Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw api::Error("out of memory");
  } catch (const std::exception& e) {
    throw api::Error(InApiTerms(e.what()));
  }
}

}  // namespace vkpt

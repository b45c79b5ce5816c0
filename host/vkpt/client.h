// The library's door for a client inside vkpt, the command line: a vkpt::Scene opened
// with the settings the API does not offer, its views begun and finished in two steps (so
// that an MPI job's ranks can render a begun frame's chunks from their own source), a
// begun view rendered on the CPU for --compare, and the times and validation messages the
// client reports. What it reports of the scene it reads from the public API. Scene::Render is BeginView, the
// local passes and FinishView, so the command line renders what the library renders.
// These leave errors in the engine's terms (the command line's); the public API's own
// functions translate them (Translated).
#pragma once

#include <exception>
#include <new>
#include <string>

#include "vkpt/api_terms.h"
#include "vkpt/settings_schema.h"
#include "vkpt/view.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal {

vkpt::Scene OpenScene(const std::string& path, const vkpt::SceneOptions& options, const ClientScene& client);
// The scene's load, pose, build and upload times so far; the client adds its own phases.
RunTimes& TimesOf(vkpt::Scene& scene);
// Vulkan validation messages reported so far (0 on the CPU or without validation).
uint32_t ValidationMessagesOf(const vkpt::Scene& scene);

BegunView BeginView(vkpt::Scene& scene, const vkpt::Camera& camera, const vkpt::RenderOptions& options,
                    const ClientView& client);
// The session settings of a begun view's render: its budget, AOV pass, filter and stop.
SessionSettings SessionOf(LoadedScene& loaded, const BegunView& view, const vkpt::RenderOptions& options,
                          const ClientView& client);
// A begun view's frame, its samples taken, with its AOV layers and the names of its ids.
RenderedView Resolved(LoadedScene& loaded, const BegunView& view, RenderedFrame frame);
// Renders a begun view from `source` (its frame's local passes, or an MPI job's dealt
// chunks), then its AOV pass and filter as the options ask.
RenderedView FinishView(vkpt::Scene& scene, BegunView& view, SampleSource& source, const vkpt::RenderOptions& options,
                        const ClientView& client);
// The camera a begun view renders from (its index among the file's cameras).
vkpt::CameraInfo CameraOf(const BegunView& view);
// --compare's reference: the begun view's frame rendered by the CPU tracer from the same
// samples, whatever the scene's backend.
RenderedFrame RenderOnCpu(vkpt::Scene& scene, const BegunView& view, const SessionSettings& settings,
                          const SessionHooks& hooks);

// Any failure inside as the one public exception, its message in the API's terms.
template <class F>
auto Translated(F&& f) {
  try {
    return f();
  } catch (const vkpt::Error&) {
    throw;
  } catch (const SettingError& e) {
    throw vkpt::SettingError(InApiTerms(e.what()));
  } catch (const std::bad_alloc&) {
    throw vkpt::Error("out of memory");
  } catch (const std::exception& e) {
    throw vkpt::Error(InApiTerms(e.what()));
  }
}

}  // namespace vkpt::internal

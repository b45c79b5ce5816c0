// The viewer's overlay: what it shows of the render (its samples, rate, time and noise)
// and the settings it changes — how the picture is shown, the render's depth, filter and
// AOV, and the scene's environment, material variant and animation — as rows of a panel
// (window/panel.h). Ranges come from the settings schema, as the command line's do.
// Building the rows and reading them back are pure, so they are tested without a window.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "image/view_transform.h"
#include "vkpt/vkpt.h"
#include "window/panel.h"

namespace vkpt::internal {

// What the panel changes.
struct PanelSettings {
  DisplayTransform display;
  uint32_t maxDepth = 32;
  bool denoise = false;
  std::string aov;  // shown instead of the image: albedo, normal, depth, object_id, material_id ("": the image)
  std::optional<double> environmentRotation, environmentIntensity;  // with an environment map
  std::vector<std::string> variants;                                // the file's
  std::string variant;                                              // "": the primitives' own materials
  std::vector<vkpt::AnimationInfo> animations;
  std::string animation;  // "": none
  double time = 0.0;
  bool playing = false;
};

// What the panel shows of the render so far.
struct PanelStats {
  uint32_t spp = 0, maxSpp = 0;
  double samplesPerSecond = 0.0, seconds = 0.0, relMse = 0.0;
  std::string engine, refused;  // refused: the last change the scene refused, if any
};

// The AOVs the panel offers, after "image".
const std::vector<std::string>& PanelAovs();

std::vector<PanelRow> PanelRows(const PanelSettings& s, const PanelStats& stats);

// What changed, as `rows` (PanelRows' after DrawPanel) tell it.
struct PanelChange {
  bool display = false;      // shown otherwise: the same render
  bool render = false;       // the render's options: begin again
  vkpt::ParameterMap scene;  // the scene's parameters to update
};
PanelChange ApplyPanel(const std::vector<PanelRow>& rows, PanelSettings& s);

// The panel's settings at the start: the render's and the display's as given, the
// scene's as it holds them. The render's time and environment rotation, if given, become
// the scene's parameters first, so that the panel's changes to them are not overridden.
PanelSettings StartPanel(vkpt::Scene& scene, const vkpt::RenderOptions& render, const DisplayTransform& display);
// The scene's values again (after a refused change).
void ReadScene(const vkpt::Scene& scene, PanelSettings& s);
// The render's options with the panel's depth, filter and AOV; its time and rotation the
// scene's.
vkpt::RenderOptions RenderOptionsOf(const vkpt::RenderOptions& render, const PanelSettings& s);
// The playing animation's time `dt` seconds on, from its start again after its end.
double AdvanceTime(const PanelSettings& s, double dt);

}  // namespace vkpt::internal

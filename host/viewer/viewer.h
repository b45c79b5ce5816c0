// The interactive viewer (vkpt --interactive): a scene rendered progressively into a
// window, the camera moved with the mouse and keys. While the camera moves each frame
// is a new render at a quarter of the size and 1 sample per pixel, so that the picture
// follows the hand (three-gpu-pathtracer's approach); once it rests, the render starts
// again at full size and accumulates. Every render is the library's ProgressiveRender,
// so what the window shows after n samples is the batch render's image at spp n. An
// overlay (viewer/viewer_panel.h) shows the render's figures and changes its settings.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "image/view_transform.h"
#include "viewer/viewer_panel.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal {

// What the window shows when P saves it: the batch command renders this.
struct ViewedFrame {
  std::optional<vkpt::Camera> camera;  // moved, or a file's camera by index; none: the first view
  uint32_t spp = 0, width = 0, height = 0;
  PanelSettings settings;  // as the overlay left them
};

struct ViewerSettings {
  std::string scene;
  vkpt::SceneOptions sceneOptions;
  vkpt::Camera camera;         // the first view (R comes back to it)
  vkpt::RenderOptions render;  // its size is the window's first; spp bounds the accumulation
  DisplayTransform display;
  std::string savePath;  // P writes the render so far here (PNG) and beside it as EXR
  // The batch command that renders what the window shows.
  std::function<std::string(const ViewedFrame&)> batchCommand;
  std::function<bool()> stop;                   // Ctrl-C: quit between frames
  std::function<void(const std::string&)> say;  // a line for the user (stdout)
};

// Opens the scene and the window and runs until Escape, the window's close or `stop`;
// returns the exit status (0). Throws Error when the scene or the window cannot open.
int RunViewer(const ViewerSettings& settings);

}  // namespace vkpt::internal

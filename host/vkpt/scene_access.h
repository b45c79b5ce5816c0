// What a vkpt::Scene holds (the engine's loaded scene and the options it was opened with),
// and the door through which the library's own files reach it.
#pragma once

#include <memory>
#include <utility>

#include "engine/loaded_scene.h"
#include "vkpt/vkpt.h"

namespace vkpt {

struct Scene::Impl {
  std::unique_ptr<internal::LoadedScene> loaded;
  // As opened, with the variant and animation Update chose: each render's settings are
  // checked with them.
  SceneOptions options;
  // The render begun by Begin, until the scene begins another, renders or updates.
  std::shared_ptr<ProgressiveRender::Impl> progressive;
};

struct v1::SceneAccess {
  static Scene Make(std::unique_ptr<internal::LoadedScene> loaded, const SceneOptions& options) {
    return Scene(std::make_unique<Scene::Impl>(Scene::Impl{std::move(loaded), options, nullptr}));
  }
  static const SceneOptions& Options(const Scene& scene) { return scene.impl_->options; }
  static SceneOptions& Options(Scene& scene) { return scene.impl_->options; }
  static internal::LoadedScene& Engine(Scene& scene) { return *scene.impl_->loaded; }
  static const internal::LoadedScene& Engine(const Scene& scene) { return *scene.impl_->loaded; }
  // Ends the progressive render begun, if any: its device frame is released.
  static void EndProgressive(Scene& scene) { scene.impl_->progressive.reset(); }
};

}  // namespace vkpt

// A glTF file loaded once, with its environment map and the device it renders on, for
// any number of renders. Each render poses the scene (again only when an animation is
// chosen and its time changes, or an edit changed the pose), builds the BVH and the
// renderers' arrays (once per pose; an edit of materials and lights alone remakes theirs),
// uploads them to the device (once per build) and makes its frame's constants from a
// camera and a picture's settings.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/render_backend.h"
#include "engine/settings.h"
#include "gltf/gltf_loader.h"
#include "render/environment_map.h"
#include "render/render_scene.h"
#include "session/aov.h"
#include "session/frame_memory.h"
#include "session/run_times.h"
#include "shared/layout.h"
#include "vk/context.h"

namespace vkpt::internal {

struct FrameRequest {
  CameraSettings camera;
  PictureSettings picture;
  // What the caller keeps per pixel (AOVs, a reference, MPI ranks, the output); the size
  // and the device are filled in from the camera and the scene.
  FrameShape shape;
  std::string name;  // names the frame in a refusal (its output file); "": the scene's file
  EngineLog log;     // what the frame's constants are warned about
};

// One render's camera, size and constants, and the memory counted for it.
struct PreparedFrame {
  Camera camera;
  uint32_t cameraIndex = 0;
  glm::uvec2 size{0};
  shader::FrameParams params{};
  std::vector<MemoryPart> parts;  // per pixel (session/frame_memory.h)
  uint64_t memory = 0;            // in all, counted against the scene's memory limit
};

class LoadedScene {
 public:
  // Reads and checks the file and the environment map, then opens the device (Backend::Auto
  // without one: the CPU, with a notice). Throws Error naming the file at fault.
  LoadedScene(const SceneSettings& settings, const EngineLog& log);
  ~LoadedScene();
  LoadedScene(const LoadedScene&) = delete;
  LoadedScene& operator=(const LoadedScene&) = delete;

  const SceneSettings& Settings() const { return settings_; }
  const Scene& scene() const { return asset_->scene(); }
  bool HasEnvironmentMap() const { return !settings_.env.empty(); }
  const vk::Context* Device() const { return ctx_.get(); }
  const RenderScene& Arrays() const { return rs_; }

  // The scene posed at the picture's time and built, the camera chosen and the frame's
  // memory counted (before anything of the frame is allocated), its constants made. A
  // frame begun before must end before this is called again.
  PreparedFrame Prepare(const FrameRequest& request);

  // This scene's renderer; the scene is uploaded to the device on first use after a build.
  const RenderBackend& Backend();
  // A frame of the last Prepare on Backend(); its time, with the upload's, goes to
  // times.upload. `batch`: Vulkan samples per pixel per submission (0: automatic).
  std::unique_ptr<FrameRenderer> BeginFrame(const shader::FrameParams& params, uint32_t batch);

  // What the id AOVs report for a scene triangle, and what the ids name (JSON), of the
  // scene as posed (scene/scene_ids.h).
  TriangleIdsOf IdsOf() const;
  std::string IdsJson() const;

  // Edits (vkpt::Scene::Update), which the next Prepare builds as a fresh load of the file
  // so edited (or so chosen) would: the BVH and every array again where triangles may have
  // moved, else only the materials and the light table (RestyleRenderScene), re-uploaded.
  // The file's nodes, lights, materials, variant and animation edited (GltfAsset::Edit),
  // and the time of renders that name none; throws Error, leaving the scene as it was,
  // where the file so edited would be refused.
  void Edit(const AssetEdits& edits, double time);
  void SetEnvironment(float intensity, float rotation);
  // The file's nodes, meshes and lights (GltfAsset): a scene loaded for one render
  // (SceneSettings::once) keeps none of them once it is built.
  const GltfAsset& Asset() const { return *asset_; }

  RunTimes times;  // load, environment, pose, prepare and upload, as they happen

  // How often the scene's arrays were built and uploaded to the device.
  struct Counts {
    uint32_t builds = 0, uploads = 0;
    uint32_t restyles = 0;  // materials and light table made again (and re-uploaded) alone
  };
  Counts Counts() const { return counts_; }

 private:
  shader::FrameParams FrameParams(const Camera& cam, glm::uvec2 size, const PictureSettings& p,
                                  const EngineLog& log) const;
  void ChargeFrame(PreparedFrame& frame, const FrameRequest& request) const;

  SceneSettings settings_;
  EngineLog log_;
  std::unique_ptr<GltfAsset> asset_;
  EnvironmentMap environment_;  // handed to the arrays once if nothing is built again
  uint64_t environmentBytes_ = 0;
  std::unique_ptr<vk::Context> ctx_;  // null: the CPU renders
  double posedAt_ = 0.0;              // the time the scene is posed at (first settings_.choice.time)
  std::optional<double> builtAt_;     // the pose rs_ holds
  bool restyle_ = false;              // rs_'s materials or lights are not the scene's
  bool studioAllowed_ = false;        // rs_ was built for a render without a map or a background
  bool studioLit_ = false;            // … and carries the studio environment (render/studio_environment.h)
  RenderScene rs_;
  std::unique_ptr<RenderBackend> backend_;  // of rs_, made on first use
  struct Counts counts_;
};

}  // namespace vkpt::internal

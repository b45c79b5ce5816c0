// What a program asks of the engine: the scene to load and on which device (SceneSettings),
// where the camera is (CameraSettings), and the picture's size and frame constants
// (PictureSettings). The library fills these from its public settings (vkpt/client.cpp),
// for its own callers and for the command line alike.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "bvh/bvh.h"
#include "gltf/gltf_loader.h"
#include "render/light_tree.h"
#include "scene/load_limits.h"

namespace vkpt::internal {

enum class Backend { Auto, Cpu, Vulkan };

struct SceneSettings {
  std::string path;    // the .gltf or .glb
  LoadLimits load;     // memory, texels, external URIs
  SceneChoice choice;  // variant and animation, and the time of renders that name none
  std::string env;     // equirectangular environment map (.hdr, .exr); "": none
  float envIntensity = 1.0f;
  float envRotation = 0.0f;  // of renders that name none: degrees about +Y, counter-clockwise seen from above
  LightSampler lightSampler = LightSampler::kAuto;
  uint32_t leafSize = 8;
  SplitMode splits = SplitMode::kAuto;
  Backend backend = Backend::Auto;  // Auto: Vulkan when a device opens, else the CPU
  std::string device;               // a Vulkan device by index or name substring
  bool validation = false;          // the Vulkan validation layer
  unsigned threads = 0;             // CPU threads (0: all cores)
  bool compare = false;             // --compare: a device is required, and the CPU's BVH layout is built as well
  // One render only: the file's data and the environment map are released as soon as the
  // scene's arrays are built, so that a large scene's peak memory holds one copy of each.
  bool once = false;
};

// A scene camera (or, in a scene without one, a camera framing it), moved and aimed.
struct CameraSettings {
  std::optional<uint32_t> index;    // the scene's camera (default 0)
  std::optional<glm::mat4> matrix;  // placed instead by this camera-to-world matrix
  std::optional<glm::vec3> lookFrom, lookAt, up;
  std::optional<double> fov;    // vertical, degrees (perspective cameras)
  std::optional<double> orbit;  // degrees about the up axis through the look-at point
};

// The most pixels an image may have on a side, given or following the camera's aspect ratio.
inline constexpr uint32_t kMaxImageSide = 16384;

// No defaults here: the library sets every field from its public RenderOptions, whose
// initialisers are the defaults (vkpt/client.cpp).
struct PictureSettings {
  std::optional<uint32_t> width, height;  // a missing side follows the camera's aspect ratio
  uint32_t seed = 0, maxDepth = 0, rrDepth = 0;
  bool textureLod = false;
  // Constant environment radiance; absent: white for a scene without light sources (so any
  // model is visible), black otherwise. Ignored with an environment map.
  std::optional<glm::vec3> background;
  std::optional<float> envRotation;  // degrees about +Y (none: SceneSettings::envRotation)
  std::optional<double> time;        // seconds into the chosen animation (none: SceneChoice::time)
};

// Where the engine's messages go; any may be empty. `warning`: something the user should
// fix; `notice`: what the engine did instead of failing; `info`: what it loaded and built.
struct EngineLog {
  std::function<void(const std::string&)> warning, notice, info;
  void Warn(const std::string& line) const {
    if (warning) warning(line);
  }
  void Notice(const std::string& line) const {
    if (notice) notice(line);
  }
  void Info(const std::string& line) const {
    if (info) info(line);
  }
};

}  // namespace vkpt::internal

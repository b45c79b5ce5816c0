// vkpt as a library: load a glTF 2.0 scene once, with the same checks the command line
// makes on untrusted files; render it any number of times, from any camera, on a Vulkan
// device or the CPU; get linear float images and AOVs as arrays. Standard C++ only.
//
//   vkpt::Scene scene("DamagedHelmet.glb");
//   vkpt::RenderOptions options;
//   options.width = 640;
//   options.aovs = {"depth", "normal"};
//   vkpt::RenderResult a = scene.Render(vkpt::Camera{}, options);   // the file's camera
//   vkpt::Camera turned;
//   turned.orbitDegrees = 90;
//   vkpt::RenderResult b = scene.Render(turned, options);           // nothing loaded again
//
// Renders of one Scene with the same options and seed are bit-identical to each other and
// to the `vkpt` command's. A Scene is used by one thread at a time; Scenes on different
// threads are independent, each with its own device context.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "vkpt/parameters.h"
#include "vkpt/scene_info.h"

// What the shared library libvkpt.so exports: these declarations and nothing else.
#if defined(__GNUC__)
#define VKPT_API __attribute__((visibility("default")))
#else
#define VKPT_API
#endif

namespace vkpt {
// The public names live in a versioned inline namespace (the ABI's); the library's own
// types live in vkpt::internal, so the two never share a name.
inline namespace v1 {

// Every failure: a file that cannot be read or is malformed, a setting out of range, a
// device that is missing, memory beyond the limit. The message names what is at fault.
class VKPT_API Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A setting out of its range (the message names the field and the range) or at odds with
// another: what the `vkpt` command refuses as a usage error.
class VKPT_API SettingError : public Error {
 public:
  using Error::Error;
};

enum class Backend {
  Auto,    // the Vulkan device when one opens, else the CPU
  Cpu,     // the CPU reference tracer
  Vulkan,  // a Vulkan compute device (an error if none opens)
};

// How light sampling chooses among emissive triangles, point and spot lights: by how
// much each may light the shading point (a light tree), by power alone, or Auto: the tree
// from 8 such lights on.
enum class LightSampler { Auto, Power, Tree };

// How much a message of SceneOptions::log matters: Warning (the image may not be what the
// file means: an ignored extension, a black image ahead, a fallback to the CPU, validation
// messages), Info (notices), Debug (what the command line prints with -v).
enum class LogLevel { Debug, Info, Warning };
using LogCallback = std::function<void(LogLevel level, const std::string& message)>;

struct SceneOptions {
  Backend backend = Backend::Auto;
  std::string device;              // a Vulkan device by index or name substring ("": the best)
  bool validation = false;         // the Vulkan validation layer; messages are counted in stats
  unsigned threads = 0;            // CPU threads (0: all cores)
  uint64_t maxMemory = 0;          // bytes the scene may need, checked before reading (0: half the RAM)
  uint64_t maxTexels = 0;          // texels of the scene's images (0: 2^28)
  bool allowExternalUris = false;  // let the file read outside its own folder
  std::string variant;             // KHR_materials_variants variant, by name or index
  std::string animation;           // an animation, by name or index; time poses it (RenderOptions)
  std::string environment;         // an equirectangular .hdr or .exr lighting the scene
  float environmentIntensity = 1.0f;
  LightSampler lightSampler = LightSampler::Auto;
  // Receives the load's and every render's messages, from the thread that loads or
  // renders (none: they are dropped).
  LogCallback log;
};

// The file's camera `index` (without cameras: one framing the scene), or its lens placed by
// `matrix`; then moved to lookFrom, aimed at lookAt with `up` up, turned about `up` through
// the look-at point (or the scene's centre) and given a vertical field of view.
struct Camera {
  std::optional<uint32_t> index;
  // Camera-to-world, column-major as glTF stores node matrices: the camera stands at its
  // translation and looks along its −Z with its +Y up.
  std::optional<std::array<float, 16>> matrix;
  std::optional<std::array<float, 3>> lookFrom, lookAt, up;
  std::optional<double> fovDegrees;
  double orbitDegrees = 0.0;
};

struct RenderOptions {
  std::optional<uint32_t> width, height;  // a missing side follows the camera's aspect (512 wide)
  std::optional<uint32_t> spp;            // at most; default 64, or 65536 with a time or noise target
  std::optional<double> seconds;          // stop after this much rendering
  std::optional<double> noiseTarget;      // stop at this estimated relMSE (turns on adaptive)
  std::optional<bool> adaptive;           // converged pixels stop taking samples
  uint32_t seed = 0;
  uint32_t maxDepth = 32, rrDepth = 3;
  uint32_t chunkSpp = 16;  // decisions fall between chunks; the image depends on it
  uint32_t batch = 0;      // Vulkan samples per pixel per submission (0: automatic)
  // Seconds into the scene's animation; none: its "time" parameter (Scene::Parameters).
  std::optional<double> time;
  // Radiance of rays that leave the scene; none: the studio environment for a scene with
  // no lights (docs/options.md, --background), else black.
  std::optional<std::array<float, 3>> background;
  // Degrees about +Y; none: the scene's "environment/rotation" parameter.
  std::optional<float> environmentRotation;
  bool textureLod = true;  // ray-cone texture filtering
  // albedo, normal, depth, position, variance, spp, heatmap, object_id, material_id,
  // instance_id; "all"
  std::vector<std::string> aovs;
  bool denoise = false;                  // image: denoised; raw: before the filter
  std::function<void(double)> progress;  // finished fraction, from the rendering thread
  // Asked between passes from the rendering thread; true ends the render there with the
  // samples taken so far (stoppedBy "cancelled"), whose image is returned as any other.
  std::function<bool()> cancel;
};

// Float values, row-major from the top row, `channels` interleaved: H × W × C.
struct Image {
  uint32_t width = 0, height = 0, channels = 0;
  std::vector<std::string> channelNames;  // {"R","G","B"}, {"X","Y","Z"}, {"Z"}, …
  std::vector<float> data;
  float At(uint32_t x, uint32_t y, uint32_t c = 0) const { return data[(size_t(y) * width + x) * channels + c]; }
};

struct RenderResult {
  Image image;               // linear Rec.709 radiance (denoised with RenderOptions::denoise)
  std::optional<Image> raw;  // with denoise: the image before the filter
  std::map<std::string, Image> aovs;
  // With an id AOV: what its ids name, as JSON ({"none": -1, "object_id": [{"id", "name",
  // "mesh"}…], "material_id": [{"id", "name"}…], "instance_id": [{"id", "object_id",
  // "placement"}…]}); else empty.
  std::string ids;
  uint32_t spp = 0;       // samples per pixel (adaptive: the most any pixel took)
  uint64_t samples = 0;   // every pixel's samples added up
  std::string stoppedBy;  // "spp", "time", "noise_target", "converged", "cancelled"
  double estimatedRelMse = 0.0;
  double seconds = 0.0;  // rendering, AOV pass and filter
  std::string engine;    // the device or "cpu"
};

struct SceneAccess;  // the command line's door to a Scene (inside vkpt, not installed)

// A render taken in steps, for a window or a preview (Scene::Begin): samples are added
// when asked, and the render so far can be read at any point. After n samples its Result
// is bit-identical to Render's at spp n with the same camera and options. It takes the
// samples it is asked for, up to RenderOptions::spp (none: 65536): a time, a noise target
// and adaptive sampling are Render's. It ends when its Scene begins another, renders,
// updates or is destroyed; its calls then throw Error.
class VKPT_API ProgressiveRender {
 public:
  ~ProgressiveRender();
  ProgressiveRender(ProgressiveRender&&) noexcept;
  ProgressiveRender& operator=(ProgressiveRender&&) noexcept;

  // Adds up to `spp` samples per pixel — fewer at the spp bound, or when the options'
  // cancel says to stop (asked between passes) — and returns the samples per pixel taken
  // so far. The options' progress receives the fraction of the spp bound reached.
  uint32_t Advance(uint32_t spp = 1);
  uint32_t Spp() const;     // samples per pixel so far
  uint32_t MaxSpp() const;  // its bound
  // The render so far, with the AOVs and the filter the options ask for, made now (the
  // AOV pass takes up to 16 samples a pixel). stoppedBy: "spp" at the bound, "cancelled"
  // when the last Advance was cancelled, else "". seconds: Advance's, the AOVs' and the
  // filter's so far.
  RenderResult Result();
  CameraInfo Camera() const;  // the camera it renders from

  struct Impl;  // the library's

 private:
  friend class Scene;
  explicit ProgressiveRender(std::weak_ptr<Impl> impl);
  std::weak_ptr<Impl> impl_;
};

class VKPT_API Scene {
 public:
  // Loads and checks the file and the environment, and opens the device. Throws Error.
  explicit Scene(const std::string& path, const SceneOptions& options = {});
  ~Scene();
  Scene(Scene&&) noexcept;
  Scene& operator=(Scene&&) noexcept;

  // Renders a view. The scene's BVH and device buffers are built once (again only when an
  // animation's time changes, or Update changed what they hold). Throws Error.
  RenderResult Render(const Camera& camera = {}, const RenderOptions& options = {});
  // Begins a render taken in steps (ProgressiveRender), ending the one begun before.
  // Throws Error, or SettingError for options it does not take.
  ProgressiveRender Begin(const Camera& camera = {}, const RenderOptions& options = {});

  uint32_t CameraCount() const;
  std::string Device() const;  // "cpu", or the Vulkan device's name

  // What the file declares (vkpt/scene_info.h): the materials (vkpt's default last), the
  // cameras and punctual lights in scene-graph order, the animations and variants.
  std::vector<MaterialInfo> Materials() const;
  std::vector<CameraInfo> Cameras() const;
  std::vector<LightInfo> Lights() const;
  // The file's nodes and meshes, by their glTF index.
  std::vector<NodeInfo> Nodes() const;
  std::vector<MeshInfo> Meshes() const;
  std::vector<AnimationInfo> Animations() const;
  std::vector<std::string> Variants() const;
  // Its counts as loaded, and as last built for a render.
  SceneStats Stats() const;

  // Every editable value (vkpt/parameters.h), as the scene holds it now.
  ParameterMap Parameters() const;
  // Applies `changes`, any of Parameters()'s keys: every value is checked first (a
  // SettingError names an unknown key, a value of the wrong kind or out of its range, and
  // then nothing changes). The next Render builds again what the changes need, without
  // reading the file — materials and lights alone: their arrays, the BVH kept — and
  // renders what a fresh load of the file so edited (or with that variant, animation and
  // time) would, bit for bit.
  void Update(const ParameterMap& changes);

 private:
  struct Impl;
  friend struct SceneAccess;
  explicit Scene(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// A Vulkan device a Scene can render on: SceneOptions::device names it by index or by a
// substring of its name.
struct Device {
  uint32_t index = 0;
  std::string name;
  std::string type;                     // "discrete GPU", "integrated GPU", "virtual GPU", "CPU" or "other"
  uint32_t apiMajor = 0, apiMinor = 0;  // the Vulkan version it supports
  bool compute = false;                 // it has a compute queue, which vkpt needs
};

// The Vulkan devices of this machine, in index order; empty without a Vulkan loader or
// driver (the CPU backend renders all the same).
VKPT_API std::vector<Device> Devices();

// Writes a render as the command line writes it, by the extension of `path`: .exr holds the
// image and its AOVs as layers ("depth.Z", …); beside a .pfm or .png each AOV goes to
// NAME.<aov>.EXT; with RenderOptions::denoise the raw image goes to NAME.raw.EXT, and the
// names of the ids (RenderResult::ids) to NAME.ids.json. A PNG shows
// the radiance after `exposure` stops through `view` ("neutral": Khronos PBR Neutral,
// "agx", "aces" or "clamp"). Each file is written whole or not at all. Returns the paths
// written, `path` first. Throws Error.
VKPT_API std::vector<std::string> Save(const RenderResult& result, const std::string& path,
                                       const std::string& view = "neutral", float exposure = 0.0f);

}  // namespace v1
}  // namespace vkpt

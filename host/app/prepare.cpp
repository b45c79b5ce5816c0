#include "app/prepare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "app/environment_option.h"
#include "app/report.h"
#include "image/image.h"
#include "render/light_table.h"
#include "scene/gltf_loader.h"
#include "scene/load_limits.h"
#include "session/aov.h"
#include "shared/sampling.h"
#include "util/atomic_write.h"
#include "util/byte_size.h"
#include "util/error.h"

namespace vkpt {
namespace {

using shader::MaxComponent;

// The camera --camera names (the scene's first, or a default one framing the scene if
// it has none); its index goes to *index.
Camera SceneCamera(const Scene& scene, const Options& o, uint32_t* index) {
  *index = o.camera.value_or(0);
  if (scene.cameras.empty()) {
    if (o.camera)
      throw Error(o.scene + ": --camera " + std::to_string(*o.camera) + " given, but the scene has no cameras");
    return DefaultCamera(scene.bounds);
  }
  if (*index >= scene.cameras.size())
    throw Error(o.scene + ": --camera " + std::to_string(*index) + " is out of range; the scene has " +
                std::to_string(scene.cameras.size()) + " camera(s)");
  return scene.cameras[*index];
}

glm::vec3 Vec3(const std::array<float, 3>& v) { return {v[0], v[1], v[2]}; }

// That camera as --look-from, --look-at, --up, --fov and --orbit move it.
Camera ChooseCamera(const Scene& scene, const Options& o, uint32_t* index) {
  Camera cam = SceneCamera(scene, o, index);
  const glm::vec3 up = o.up ? Vec3(*o.up) : glm::vec3(0.0f, 1.0f, 0.0f);
  const glm::vec3 pivot = o.lookAt ? Vec3(*o.lookAt) : scene.bounds.Center();
  try {
    if (o.lookFrom || o.lookAt || o.up) {
      const glm::vec3 from = o.lookFrom ? Vec3(*o.lookFrom) : cam.position;
      const glm::vec3 at = o.lookAt ? pivot : o.lookFrom ? scene.bounds.Center() : cam.position + cam.forward;
      cam = LookAt(cam, from, at, up);
      cam.name += " moved by --look-from/--look-at/--up";
    }
    if (o.orbit) {
      cam = Orbit(cam, pivot, up, float(*o.orbit));
      cam.name += ", turned by --orbit";
    }
  } catch (const Error& e) {
    throw Error(o.scene + ": " + e.what());
  }
  if (o.fov) {
    if (cam.orthographic)
      throw Error(o.scene + ": --fov is for perspective cameras, and camera " + std::to_string(*index) +
                  " is orthographic");
    cam.yfov = float(*o.fov * 3.14159265358979323846 / 180.0);
  }
  return cam;
}

// Resolution: what the user said; the missing side follows the camera's aspect ratio.
glm::uvec2 ImageSize(const Camera& cam, const Options& o) {
  float aspect = cam.aspectRatio > 0.0f ? cam.aspectRatio : 1.0f;
  uint32_t width = o.width.value_or(o.height ? uint32_t(std::lround(*o.height * aspect)) : 512u);
  uint32_t height = o.height.value_or(uint32_t(std::lround(width / aspect)));
  return {std::max(1u, std::min(width, 16384u)), std::max(1u, std::min(height, 16384u))};
}

// The Vulkan context for --backend vulkan (errors are fatal) or auto (no device: the
// CPU renders, after saying why).
std::unique_ptr<vk::Context> OpenVulkan(const Options& o) {
  if (o.backend == Backend::Cpu && !o.compare) return nullptr;
  // lavapipe reads LP_NUM_THREADS when the device is created: --threads applies to it too.
  if (o.threads) setenv("LP_NUM_THREADS", std::to_string(o.threads).c_str(), 1);
  vk::ContextOptions opt;
  opt.validation = o.validation;
  opt.device = o.device;
  if (o.backend == Backend::Vulkan || o.compare || !o.device.empty() || o.validation)
    return std::make_unique<vk::Context>(opt);
  try {
    return std::make_unique<vk::Context>(opt);
  } catch (const Error& e) {
    std::fprintf(stderr, "vkpt: %s\nvkpt: rendering on the CPU instead\n", e.what());
    return nullptr;
  }
}
// The BVH and the renderers' arrays, with the environment map. `gpu`: a Vulkan device will
// render, so the shader's direction-ordered copies of the tree are built; the CPU's layout
// only where the CPU renders (no device, or --compare).
RenderScene PrepareForRender(const Scene& scene, const Options& o, bool gpu, EnvironmentMap env) {
  BvhBuildOptions bvhOptions;
  bvhOptions.maxLeafSize = o.leafSize;
  bvhOptions.splits = o.splits;
  bvhOptions.threads = o.threads;
  bvhOptions.directionCopies = gpu;
  RenderScene rs = PrepareRenderScene(scene, bvhOptions, !gpu || o.compare);
  rs.environment = std::move(env);
  if (rs.environment.width > 0) AddEnvironmentLight(rs, o.envIntensity);
  return rs;
}

// The frame constants from the options; a scene without light sources (HasLightSources)
// is lit by a white environment unless --env or --background says otherwise (and is warned about if that is
// black).
shader::FrameParams FrameFromOptions(const RenderScene& rs, const Camera& cam, glm::uvec2 size, const Options& o,
                                     bool report) {
  shader::FrameParams params = MakeFrameParams(rs, cam, size.x, size.y);
  params.seed = o.seed;
  params.sampleBegin = 0;
  params.sampleCount = o.spp;
  params.maxDepth = o.maxDepth;
  params.rrDepth = o.rrDepth;
  params.textureLod = o.textureLod ? 1u : 0u;
  if (!o.env.empty()) {
    SetEnvironmentParams(params, rs.environment, o.envRotation, o.envIntensity);
  } else if (o.background) {
    params.background = glm::vec3((*o.background)[0], (*o.background)[1], (*o.background)[2]);
  } else if (!HasLightSources(rs)) {
    params.background = glm::vec3(1.0f);
    if (report && o.verbose)
      std::printf("  no lights%s: lit by a white environment (see --background)\n",
                  rs.lights.empty() ? "" : " but emissive textures");
  }
  if (report && rs.lights.empty() && o.env.empty() && MaxComponent(params.background) <= 0.0f)
    std::fprintf(stderr, "vkpt: warning: %s: no lights and a black background; the image will be black\n",
                 o.scene.c_str());
  return params;
}

// The frame's memory (session/frame_memory.h) on top of the scene's and the map's,
// against --max-memory, before the device or the film allocates any of it.
void CountFrameMemory(Prepared& p, const Options& o, glm::uvec2 size, uint64_t envBytes, uint32_t ranks) {
  FrameShape shape;
  shape.width = size.x;
  shape.height = size.y;
  shape.gpu = p.ctx != nullptr;
  // A discrete GPU's buffers are its own; any other device's live in this process's memory.
  shape.deviceInHost = !p.ctx || p.ctx->Properties().deviceType != VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU;
  shape.compare = o.compare;
  shape.ranks = ranks;
  shape.aovPass = o.denoise || std::any_of(o.aovs.begin(), o.aovs.end(), NeedsAovPass);
  shape.aovChannels = AovChannels(o.aovs);
  shape.denoise = o.denoise;
  shape.exrOutput = FormatFromPath(o.out) == ImageFormat::Exr;
  p.frameParts = FrameMemoryParts(shape);
  p.frameMemory = BytesPerPixel(p.frameParts) * size.x * size.y;
  MemoryBudget budget(p.scene().memoryLimit, o.out);
  budget.Charge(p.scene().memoryCounted + envBytes, "the scene and environment");
  budget.Charge(
      p.frameMemory,
      "a " + std::to_string(size.x) + " × " + std::to_string(size.y) + " image (" + DescribeParts(p.frameParts) + ")",
      "lower --width and --height, or raise --max-memory");
}

}  // namespace

void PrepareFrame(Prepared& p, const Options& o, bool report, uint32_t ranks) {
  PhaseTimer phase;
  // A sequence without an animation (a turntable) poses the same scene every frame: only
  // the camera moves, so the first frame's arrays serve them all.
  const bool sameScene = o.frames && p.built && p.scene().animation < 0;
  if (!sameScene) p.asset->PoseAt(o.at.value_or(0.0));
  if (!o.frames) p.asset->ReleaseSource();  // a single image: the file's data is done with
  phase.Lap(p.times.pose);
  uint32_t camIndex = 0;
  const Camera cam = ChooseCamera(p.scene(), o, &camIndex);
  const glm::uvec2 size = ImageSize(cam, o);
  // A sequence keeps the map for its next frame (counted twice); one image hands it over.
  const bool keep = o.frames.has_value();
  CountFrameMemory(p, o, size, p.environmentBytes * (keep ? 2 : 1), ranks);
  phase.Restart();
  if (!sameScene) {
    p.rs = RenderScene{};  // the last frame's arrays go before the next's are built
    p.rs = PrepareForRender(p.scene(), o, p.ctx != nullptr, keep ? p.environment : std::move(p.environment));
    p.built = true;
  }
  phase.Lap(p.times.prepare);
  if (report && o.verbose) {
    PrintLoadReport(p.scene(), p.rs, cam, camIndex);
    std::printf("  memory: %s counted for the %u × %u image (%s)\n", FormatBytes(p.frameMemory).c_str(), size.x, size.y,
                DescribeParts(p.frameParts).c_str());
  }
  p.params = FrameFromOptions(p.rs, cam, size, o, report);
}

Prepared Prepare(const Options& o, bool report, uint32_t ranks) {
  Prepared p;
  CheckOutputPath(o.out);  // fail before a long render, not after
  if (!o.stats.empty()) CheckWritablePath(o.stats, "a stats");
  PhaseTimer phase;
  p.asset = std::make_unique<GltfAsset>(o.scene, o.load, SceneChoice{o.variant, o.animation});
  phase.Lap(p.times.load);
  p.environment = LoadEnvironment(o, p.scene(), &p.environmentBytes);
  phase.Lap(p.times.environment);
  // The device before the scene's arrays: without one (auto backend) the CPU renders, and
  // only then does the scene need the CPU's BVH layout.
  p.ctx = OpenVulkan(o);
  PrepareFrame(p, o, report, ranks);
  return p;
}

}  // namespace vkpt

// Command-line options of `vkpt`; each is a row of the one option table (app/option_table.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bvh/bvh.h"
#include "engine/settings.h"
#include "image/aov_layer.h"
#include "image/view_transform.h"
#include "scene/load_limits.h"
#include "session/budget.h"
#include "session/chunked_frame.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal {

// --frames FIRST:LAST[:STEP]: the frame numbers FIRST, FIRST + STEP, … up to LAST.
struct FrameRange {
  uint32_t first = 0, last = 0, step = 1;
};

struct Options {
  std::string scene;
  std::string out;  // default: <scene name>.png in the current directory
  std::string outGiven;  // --out exactly as given ("" when absent)
  std::optional<uint32_t> width, height;
  std::optional<uint32_t> spp;        // --spp: the most samples a pixel takes (Budget() says the default)
  std::optional<double> time;         // --time: seconds of rendering
  std::optional<double> noiseTarget;  // --noise-target: estimated relMSE that ends the render
  std::optional<bool> adaptive;       // --adaptive / --no-adaptive; absent: on with --noise-target
  double checkpoint = 0.0;            // --checkpoint: seconds between rewrites of --out (0: none)
  // The library's defaults (vkpt/vkpt.h) are the command line's.
  uint32_t seed = vkpt::RenderOptions{}.seed;
  uint32_t chunkSpp = vkpt::RenderOptions{}.chunkSpp;  // --chunk
  uint32_t maxDepth = vkpt::RenderOptions{}.maxDepth;
  uint32_t rrDepth = vkpt::RenderOptions{}.rrDepth;
  vkpt::Backend backend = vkpt::SceneOptions{}.backend;  // Auto: Vulkan when a device exists, else the CPU
  std::string device;               // --device N|substring
  bool listDevices = false;
  bool validation = false;          // --validation or VKPT_VALIDATION=1
  uint32_t batch = vkpt::RenderOptions{}.batch;  // samples per pixel per GPU submission; 0 = auto
  bool compare = false;             // render on both backends and compare
  std::vector<std::string> diff;    // --diff A.pfm B.pfm: compare two existing images
  unsigned threads = vkpt::SceneOptions{}.threads;  // 0: all cores
  std::optional<uint32_t> camera;
  // --look-from, --look-at, --up: the camera moved and aimed (scene/scene.h's LookAt);
  // --fov: its vertical field of view in degrees; --orbit: degrees it turns about the up
  // axis through the look-at point (Orbit).
  std::optional<std::array<float, 3>> lookFrom, lookAt, up;
  std::optional<double> fov, orbit;
  float exposure = 0.0f;       // --exposure: stops, PNG only
  View view = View::kNeutral;  // --view: how a PNG shows radiance
  DisplayTransform Display() const { return {view, exposure}; }
  // Constant environment radiance; absent: white (1,1,1) for a scene without emissive
  // triangles (so any model is visible), black otherwise.
  std::optional<std::array<float, 3>> background;
  std::string env;           // --env: equirectangular environment map (.hdr, .exr)
  std::string variant;       // --variant: a KHR_materials_variants name or index ("": none)
  std::string animation;     // --animation: a glTF animation's name or index ("": none)
  std::optional<double> at;  // --at: seconds into the animation
  // --frames: a sequence of renders, frame k posed k / --fps seconds into the animation and
  // turned by k × --orbit; each written to FramePath(out, k).
  std::optional<FrameRange> frames;
  double fps = 24.0;
  float envRotation =
      vkpt::RenderOptions{}.environmentRotation;  // --env-rotation: degrees about +Y, counter-clockwise from above
  float envIntensity = vkpt::SceneOptions{}.environmentIntensity;  // --env-intensity: radiance scale
  uint32_t leafSize = 8;
  SplitMode splits = SplitMode::kAuto;  // --splits
  vkpt::LightSampler lightSampler = vkpt::SceneOptions{}.lightSampler;  // --light-sampler
  bool textureLod = vkpt::RenderOptions{}.textureLod;                   // --texture-lod cones (true) or none
  LoadLimits load;                      // --max-memory, --allow-external-uris
  std::string stats;                    // --stats FILE.json: the run described as JSON (app/run_stats.h)
  std::vector<Aov> aovs;                // --aov: written with the image (image/aov_files.h), in the order given
  bool denoise = false;                 // --denoise: --out denoised (render/denoise.h), the raw image beside it
  bool verbose = false;
  bool help = false;
  bool version = false;

  // The render's budget, as the library derives it (spp bound included).
  RenderBudget Budget() const { return BudgetFor({spp, time, noiseTarget, adaptive, checkpoint, chunkSpp}); }
};

// Throws UsageError for anything malformed; the message says which option and why.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

Options ParseOptions(int argc, const char* const* argv);
std::string HelpText();

}  // namespace vkpt::internal

#include "app/options.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>

#include "util/byte_size.h"

namespace vkpt {
namespace {

template <class T>
T ParseNumber(const std::string& opt, const std::string& text, T lo, T hi) {
  T v{};
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size())
    throw UsageError(opt + " expects a number, got \"" + text + "\"");
  if (!(v >= lo && v <= hi))
    throw UsageError(opt + " must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + text);
  return v;
}

}  // namespace

std::string HelpText() {
  return R"(usage: vkpt --scene FILE [options]
       vkpt --diff A.pfm B.pfm [--out heatmap.png]
       vkpt --list-devices

Renders a glTF 2.0 scene (.gltf or .glb) by Monte Carlo path tracing.

  --scene FILE       glTF scene to render (required)
  --out FILE         output image; .png (8-bit sRGB), .pfm or .exr (linear float)
                     [default: <scene name>.png]
  --width N          image width in pixels   [default: 512]
  --height N         image height in pixels  [default: from the camera's aspect ratio, else 512]
  --spp N            samples per pixel; with --time or --noise-target the most any pixel
                     takes [default: 64; 65536 with --time or --noise-target]
  --time SECONDS     render passes until SECONDS of rendering are spent (after loading,
                     BVH build and upload); every pixel gets the same samples
  --noise-target X   stop once the image's estimated relMSE (from each pixel's variance,
                     as vkpt-bench measures against a reference) is at most X, checked
                     at 16, 24, 32, 40, 50... spp rounded up to whole chunks (16, 32,
                     48, 64, 80, 96, 128... with --chunk 16); turns on --adaptive
  --adaptive         adaptive sampling: at those same counts, pixels whose estimated
                     error (and their neighbours') is below --noise-target, else 1e-3,
                     stop taking samples [default: on with --noise-target]
  --no-adaptive      every pixel takes samples until the render stops
  --aov LIST         also write these AOVs, comma-separated: albedo, normal, depth,
                     position, variance, spp, heatmap (BVH boxes tested per camera ray),
                     or all; layers of the same file for an .exr --out, else
                     <out name>.<aov>.<ext> beside it (README, "AOVs")
  --denoise          write --out denoised by vkpt's edge-avoiding a-trous filter (guided
                     by the albedo, normal and depth AOVs and the pixels' variance) and
                     the raw image beside it as <out name>.raw.<ext>
  --checkpoint SECONDS
                     rewrite --out every SECONDS during the render, with the samples so far
  --seed N           random seed; same seed and device give a bit-identical image [default: 0]
  --chunk N          samples per pixel per chunk: each chunk is summed on its own and the
                     chunks added in order, so the image depends on N (as on the seed)
                     but not on passes or MPI ranks [default: 16]
  --max-depth N      maximum number of bounces [default: 32]
  --rr-depth N       bounces before Russian roulette starts [default: 3]
  --backend NAME     vulkan (compute shader on a Vulkan device), cpu (reference path
                     tracer) or auto (vulkan if a device exists, else cpu) [default: auto]
  --device N|NAME    Vulkan device by index or name substring [default: discrete GPU >
                     integrated > virtual > CPU (lavapipe)]
  --list-devices     list Vulkan devices and exit
  --validation       enable the Vulkan validation layer (also VKPT_VALIDATION=1); any
                     validation message makes vkpt exit with status 3
  --batch N          Vulkan: samples per pixel per submission [default: ~1M paths each]
  --threads N        CPU threads; also LP_NUM_THREADS for lavapipe [default: all cores]
  --compare          render on the CPU and on Vulkan with the same seed and report how
                     they agree; writes the Vulkan image to --out and a heat map of the
                     differences to <out>-diff.png; exit status 4 if they disagree
  --diff A B         compare two .pfm images (no rendering): per-channel mean difference,
                     region tests, NaN/Inf counts; heat map to --out if given; exit
                     status 4 if they differ beyond statistics
  --camera N         index of the glTF camera to render from, in scene order [default: 0;
                     a scene without cameras gets one that frames it]
  --background R,G,B constant environment radiance seen by rays that leave the scene
                     (one number for grey) [default: 1 if the scene has no lights
                     (punctual lights, or emissive triangles not painted by an emissive
                     texture), so any model is lit; else 0]
  --env FILE         equirectangular environment map, .hdr (Radiance RGBE) or .exr, lighting
                     the scene from every direction instead of --background; its centre
                     column faces -Z (where a default glTF camera looks), 3/4 of its width
                     +X, its top row +Y
  --env-rotation DEGREES
                     turn the map about +Y, counter-clockwise seen from above: 90 brings
                     what faced -Z to -X [default: 0]
  --env-intensity X  scale the map's radiance by X >= 0 [default: 1]
  --exposure STOPS   PNG only: scale radiance by 2^STOPS before sRGB encoding [default: 0]
  --texture-lod MODE mip levels of texture lookups: cones (each path's ray cone picks the
                     level its footprint covers) or none (level 0 everywhere, which
                     the samples of each pixel then average) [default: cones]
  --leaf-size N      maximum triangles per BVH leaf, 1..15 [default: 8]
  --splits MODE      how the BVH divides the scene: object (each triangle in one leaf),
                     spatial (planes may also cut triangles, which then sit in several
                     leaves clipped: faster rays where long thin triangles overlap, as in
                     CAD models; a build several times slower) or auto (build both, keep
                     the tree with the lower SAH cost) [default: auto]
  --max-memory SIZE  host memory a scene may need (its files, decoded data, triangles
                     through to the renderer's arrays), checked before it is read or
                     allocated; bytes or K/M/G/T [default: half of physical RAM]
  --max-texels N      texels the scene's texture images may have (level 0, before mip
                     levels), checked from their headers before any is decoded; a
                     count or with K/M/G (binary) [default: 256M]
  --allow-external-uris
                     let the glTF read files outside its own folder (absolute paths,
                     "..", file:// URLs, symbolic links leading out, the current
                     directory); by default a glTF reads only files beside it
  --stats FILE       write the run as one JSON object (version, scene hash, device,
                     options, times, rays, rates, mean radiance, BVH, warnings; schema
                     in the README), after the image
  -v, --verbose      print what was loaded, which glTF features were ignored, and a line
                     per rendering pass
  -h, --help         print this help and exit
  --version          print the version and exit

SIGINT or SIGTERM during the render stops it after the current pass (about a second)
and writes the image of the samples taken; a second one exits at once.

Under mpirun (built with MPI: see --version), the processes share one frame by chunks
and rank 0 writes the image, bit-identical to one process's (README, "Distributed
rendering").

Exit status: 0 success, 1 error (bad scene, I/O, device), 2 usage error,
3 Vulkan validation messages were reported, 4 --compare/--diff found a disagreement,
130/143 stopped by SIGINT/SIGTERM (the image of the samples taken was written).
)";
}

Options ParseOptions(int argc, const char* const* argv) {
  Options o;
  using Handler = std::function<void(const std::string& opt, const std::string& value)>;
  auto u32 = [](uint32_t& dst, uint32_t lo, uint32_t hi) {
    return Handler([&dst, lo, hi](const std::string& opt, const std::string& v) { dst = ParseNumber(opt, v, lo, hi); });
  };
  // A string that must not be empty; `what` completes "needs ..." in the error.
  auto text = [](std::string& dst, const char* what) {
    return Handler([&dst, what](const std::string& opt, const std::string& v) {
      if (v.empty()) throw UsageError(opt + " needs " + what);
      dst = v;
    });
  };
  auto optU32 = [](std::optional<uint32_t>& dst, uint32_t lo, uint32_t hi) {
    return Handler([&dst, lo, hi](const std::string& opt, const std::string& v) { dst = ParseNumber(opt, v, lo, hi); });
  };
  const std::map<std::string, Handler> withValue = {
      {"--scene", [&](const std::string&, const std::string& v) { o.scene = v; }},
      {"--out", [&](const std::string&, const std::string& v) { o.out = o.outGiven = v; }},
      {"--width", optU32(o.width, 1, 16384)},
      {"--height", optU32(o.height, 1, 16384)},
      {"--spp",
       [&](const std::string& opt, const std::string& v) {
         o.spp = ParseNumber(opt, v, 1u, 1u << 30);
         o.sppGiven = true;
       }},
      {"--time", [&](const std::string& opt, const std::string& v) { o.time = ParseNumber(opt, v, 1e-3, 1e7); }},
      {"--noise-target",
       [&](const std::string& opt, const std::string& v) { o.noiseTarget = ParseNumber(opt, v, 1e-9, 1.0); }},
      {"--checkpoint",
       [&](const std::string& opt, const std::string& v) { o.checkpoint = ParseNumber(opt, v, 1e-3, 1e7); }},
      {"--seed", u32(o.seed, 0, 0xFFFFFFFFu)},
      {"--chunk", u32(o.chunkSpp, 1, 1u << 30)},
      {"--max-depth", u32(o.maxDepth, 0, 1024)},
      {"--rr-depth", u32(o.rrDepth, 0, 1024)},
      {"--threads", [&](const std::string& opt, const std::string& v) { o.threads = ParseNumber(opt, v, 1u, 1024u); }},
      {"--camera", optU32(o.camera, 0, 1u << 20)},
      {"--leaf-size", u32(o.leafSize, 1, 15)},
      {"--batch", u32(o.batch, 1, 1u << 30)},
      {"--device", text(o.device, "a device index or name")},
      {"--exposure",
       [&](const std::string& opt, const std::string& v) { o.exposure = ParseNumber(opt, v, -64.0f, 64.0f); }},
      {"--background",
       [&](const std::string& opt, const std::string& v) {
         std::vector<std::string> parts;
         for (size_t start = 0;;) {
           size_t comma = v.find(',', start);
           parts.push_back(v.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
           if (comma == std::string::npos) break;
           start = comma + 1;
         }
         if (parts.size() != 1 && parts.size() != 3)
           throw UsageError(opt + " expects R,G,B or one number, got \"" + v + "\"");
         std::array<float, 3> c{};
         for (size_t k = 0; k < 3; ++k) c[k] = ParseNumber(opt, parts[parts.size() == 1 ? 0 : k], 0.0f, 1e30f);
         o.background = c;
       }},
      {"--env", text(o.env, "an .hdr or .exr file")},
      {"--aov",
       [&](const std::string& opt, const std::string& v) {
         o.aovs.clear();
         for (size_t start = 0;;) {
           const size_t comma = v.find(',', start);
           const std::string name = v.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
           if (name == "all") {
             for (int k = 0; k < kAovCount; ++k) o.aovs.push_back(Aov(k));
           } else if (std::optional<Aov> aov = AovFromName(name)) {
             if (std::find(o.aovs.begin(), o.aovs.end(), *aov) == o.aovs.end()) o.aovs.push_back(*aov);
           } else {
             throw UsageError(opt + ": unknown AOV \"" + name +
                              "\" (albedo, normal, depth, position, variance, spp, heatmap or all)");
           }
           if (comma == std::string::npos) break;
           start = comma + 1;
         }
       }},
      {"--stats", text(o.stats, "a file name")},
      {"--env-rotation",
       [&](const std::string& opt, const std::string& v) { o.envRotation = ParseNumber(opt, v, -3600.0f, 3600.0f); }},
      {"--env-intensity",
       [&](const std::string& opt, const std::string& v) { o.envIntensity = ParseNumber(opt, v, 0.0f, 1e30f); }},
      {"--texture-lod",
       [&](const std::string&, const std::string& v) {
         if (v != "cones" && v != "none") throw UsageError("--texture-lod must be cones or none, got \"" + v + "\"");
         o.textureLod = v == "cones";
       }},
      {"--splits",
       [&](const std::string&, const std::string& v) {
         std::optional<SplitMode> mode = ParseSplitMode(v);
         if (!mode) throw UsageError("--splits must be auto, object or spatial, got \"" + v + "\"");
         o.splits = *mode;
       }},
      {"--max-memory",
       [&](const std::string& opt, const std::string& v) {
         std::optional<uint64_t> bytes = ParseByteSize(v);
         if (!bytes || *bytes < (uint64_t(1) << 20))
           throw UsageError(opt + " expects a size of at least 1M (bytes, or with K, M, G or T), got \"" + v + "\"");
         o.load.maxMemory = *bytes;
       }},
      {"--max-texels",
       [&](const std::string& opt, const std::string& v) {
         std::optional<uint64_t> texels = ParseByteSize(v);
         if (!texels || *texels < 1 || *texels > (uint64_t(1) << 31))
           throw UsageError(opt + " expects a count from 1 to 2G (a number, or with K, M or G), got \"" + v + "\"");
         o.load.maxTextureTexels = *texels;
       }},
      {"--backend",
       [&](const std::string&, const std::string& v) {
         if (v == "cpu") o.backend = Backend::Cpu;
         else if (v == "vulkan") o.backend = Backend::Vulkan;
         else if (v == "auto") o.backend = Backend::Auto;
         else throw UsageError("--backend must be auto, vulkan or cpu, got \"" + v + "\"");
       }},
  };
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    std::string value;
    bool inlineValue = false;
    if (size_t eq = arg.find('='); arg.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
      inlineValue = true;
    }
    if (arg == "-h" || arg == "--help") { o.help = true; continue; }
    if (arg == "--version") { o.version = true; continue; }
    if (arg == "-v" || arg == "--verbose") { o.verbose = true; continue; }
    if (arg == "--list-devices") { o.listDevices = true; continue; }
    if (arg == "--validation") { o.validation = true; continue; }
    if (arg == "--compare") { o.compare = true; continue; }
    if (arg == "--denoise") {
      o.denoise = true;
      continue;
    }
    if (arg == "--adaptive") {
      o.adaptive = true;
      continue;
    }
    if (arg == "--no-adaptive") {
      o.adaptive = false;
      continue;
    }
    if (arg == "--allow-external-uris") { o.load.allowExternalUris = true; continue; }
    if (arg == "--diff") {
      if (inlineValue || i + 2 >= argc) throw UsageError("--diff needs two image files: --diff A.pfm B.pfm");
      o.diff = {argv[i + 1], argv[i + 2]};
      i += 2;
      continue;
    }
    auto it = withValue.find(arg);
    if (it == withValue.end()) throw UsageError("unknown option \"" + arg + "\" (see --help)");
    if (!inlineValue) {
      if (i + 1 >= argc) throw UsageError(arg + " needs a value");
      value = argv[++i];
    }
    it->second(arg, value);
  }
  if (const char* env = std::getenv("VKPT_VALIDATION"); env && std::string(env) == "1") o.validation = true;
  if (o.help || o.version || o.listDevices) return o;
  if (!o.diff.empty()) {
    if (!o.scene.empty() || o.compare || !o.stats.empty())
      throw UsageError("--diff compares two images; it takes no --scene, --compare or --stats");
    return o;
  }
  if (o.compare && o.backend != Backend::Auto) throw UsageError("--compare uses both backends; drop --backend");
  if (o.compare && (o.time || o.noiseTarget || o.Adaptive()))
    throw UsageError(
        "--compare renders both backends with the same samples; it takes no --time, --noise-target or --adaptive");
  if (o.compare && (!o.aovs.empty() || o.denoise))
    throw UsageError("--compare checks the backends against each other; it takes no --aov or --denoise");
  if (!o.sppGiven && (o.time || o.noiseTarget)) o.spp = kBudgetMaxSpp;
  if (o.scene.empty()) throw UsageError("--scene FILE is required (see --help)");
  if (!o.env.empty() && o.background) throw UsageError("--env and --background both set the environment; give one");
  if (o.env.empty() && (o.envRotation != 0.0f || o.envIntensity != 1.0f))
    throw UsageError("--env-rotation and --env-intensity apply to an --env map; none was given");
  if (o.out.empty()) {
    std::string base = o.scene.substr(o.scene.find_last_of('/') + 1);
    o.out = base.substr(0, base.find_last_of('.')) + ".png";
  }
  if (o.stats == o.out) throw UsageError("--stats and --out name the same file \"" + o.out + "\"");
  return o;
}

}  // namespace vkpt

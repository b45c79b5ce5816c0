#include "app/option_table.h"

#include <algorithm>
#include <sstream>
#include <utility>

#include "vkpt/setting_choices.h"

namespace vkpt::internal {
namespace {

OptionDef Row(std::vector<std::string> names, std::string value, std::string meaning, std::string defaultText,
              OptionValue how) {
  return {std::move(names), std::move(value), std::move(meaning), std::move(defaultText), std::move(how)};
}

using O = Options;

// The defaults shown are the library's own (vkpt/vkpt.h), which are the command line's.
const vkpt::RenderOptions kRender;

// The image, its samples and how they are taken.
std::vector<OptionDef> RenderRows() {
  return {
      Row({"--scene"}, "FILE", "glTF 2.0 scene to render, `.gltf` or `.glb` (required)", "", Text(&O::scene)),
      Row({"--out"}, "FILE", "output image: `.png` (8-bit sRGB), `.pfm` or `.exr` (linear float), written atomically",
          "`<scene name>.png`", OutValue()),
      Row({"--width"}, "N", "image width in pixels; give one side and the other follows the camera's aspect ratio",
          "512", Number(&O::width, SettingRange("width"))),
      Row({"--height"}, "N", "image height in pixels", "from the camera's aspect ratio, else 512",
          Number(&O::height, SettingRange("height"))),
      Row({"--spp"}, "N", "samples per pixel; with `--time` or `--noise-target` the most any pixel takes",
          FormatNumber(kDefaultSpp) + "; " + FormatNumber(kBudgetMaxSpp) + " with `--time` or `--noise-target`",
          SppValue()),
      Row({"--time"}, "SECONDS",
          "render passes until SECONDS of rendering are spent (after loading, BVH build and upload)", "none",
          Number(&O::time, SettingRange("seconds"))),
      Row({"--noise-target"}, "X", "stop once the image's estimated relMSE is at most X; turns on `--adaptive`", "none",
          Number(&O::noiseTarget, SettingRange("noise_target"))),
      Row({"--adaptive"}, "",
          "adaptive sampling: a pixel stops once its and its neighbours' estimated error is below `--noise-target`",
          "on with `--noise-target`", AdaptiveValue(true)),
      Row({"--no-adaptive"}, "", "every pixel takes samples until the render stops", "", AdaptiveValue(false)),
      Row({"--aov"}, "LIST", "also write these AOVs, in layers of an `.exr` `--out`, else in files beside it", "none",
          AovValue()),
      Row({"--denoise"}, "",
          "write `--out` denoised by vkpt's own filter and the raw image beside it as `NAME.raw.EXT`", "off",
          Flag(&O::denoise)),
      Row({"--checkpoint"}, "SECONDS", "rewrite `--out` every SECONDS during the render, with the samples so far",
          "none", CheckpointValue()),
      Row({"--seed"}, "N", "random seed; same seed and device give a bit-identical image", FormatNumber(kRender.seed),
          Number(&O::seed, SettingRange("seed"))),
      Row({"--chunk"}, "N", "samples per pixel per chunk: the image depends on N, not on passes or MPI ranks",
          FormatNumber(kRender.chunkSpp), Number(&O::chunkSpp, SettingRange("chunk_spp"))),
      Row({"--max-depth"}, "N", "maximum number of bounces (0: emission seen directly only)",
          FormatNumber(kRender.maxDepth), Number(&O::maxDepth, SettingRange("max_depth"))),
      Row({"--rr-depth"}, "N", "bounces before Russian roulette starts", FormatNumber(kRender.rrDepth),
          Number(&O::rrDepth, SettingRange("rr_depth"))),
  };
}

// Which renderer and device, and the modes that compare instead of render.
std::vector<OptionDef> DeviceRows() {
  return {
      Row({"--backend"}, "NAME",
          "renderer: `vulkan` (compute shader), `cpu` (reference) or `auto` (vulkan if a device exists)", "auto",
          Choice(&O::backend, BackendChoices())),
      Row({"--device"}, "N|NAME", "Vulkan device by index or name substring", "discrete > integrated > virtual > CPU",
          Text(&O::device, "a device index or name")),
      Row({"--list-devices"}, "", "list Vulkan devices and exit", "", NoStats(Flag(&O::listDevices))),
      Row({"--validation"}, "", "Vulkan validation layer (also `VKPT_VALIDATION=1`); any message: exit status 3", "off",
          Flag(&O::validation)),
      Row({"--batch"}, "N", "Vulkan: samples per pixel per queue submission (0: automatic)",
          "about 2^20 paths per submission", Number(&O::batch, SettingRange("batch"))),
      Row({"--threads"}, "N", "CPU threads (0: all cores); also `LP_NUM_THREADS` for lavapipe", "all cores",
          Number(&O::threads, SettingRange("threads"))),
      Row({"--compare"}, "", "render on the CPU and on Vulkan with the same seed and report how they agree", "",
          Flag(&O::compare)),
      Row({"--diff"}, "A B", "compare two `.pfm` images without rendering; heat map to `--out` if given", "",
          DiffValue()),
  };
}

// Where the camera stands and looks.
std::vector<OptionDef> CameraRows() {
  return {
      Row({"--camera"}, "N", "glTF camera to render from, in scene order; without one, a camera framing the scene", "0",
          Number(&O::camera, SettingRange("index"))),
      Row({"--look-from"}, "X,Y,Z", "move the camera to this point (scene units)", "the camera's position",
          PointValue(&O::lookFrom, "look_from")),
      Row({"--look-at"}, "X,Y,Z", "aim the camera at this point",
          "the scene's centre with `--look-from`, else straight ahead", PointValue(&O::lookAt, "look_at")),
      Row({"--up"}, "X,Y,Z", "the direction that is up in the image", "+Y, glTF's up", PointValue(&O::up, "up")),
      Row({"--fov"}, "DEGREES", "vertical field of view of a perspective camera", "the camera's",
          Number(&O::fov, SettingRange("fov"))),
      Row({"--orbit"}, "DEGREES",
          "turn the camera about the up axis through `--look-at` (else the scene's centre), counter-clockwise seen "
          "from above",
          FormatNumber(vkpt::Camera{}.orbitDegrees), Number(&O::orbit, SettingRange("orbit"))),
  };
}

// The scene as rendered and its limits.
std::vector<OptionDef> SceneRows() {
  return {
      Row({"--background"}, "R,G,B", "constant environment radiance for rays that leave the scene (one number: grey)",
          "1 if the scene has no lights, else 0", BackgroundValue()),
      Row({"--env"}, "FILE",
          "equirectangular environment map, `.hdr` or `.exr`, lighting the scene instead of a background", "none",
          Text(&O::env, "an .hdr or .exr file")),
      Row({"--env-rotation"}, "DEGREES", "turn the map about +Y, counter-clockwise seen from above",
          FormatNumber(kRender.environmentRotation), Number(&O::envRotation, SettingRange("environment_rotation"))),
      Row({"--env-intensity"}, "X", "multiply the map's radiance by X",
          FormatNumber(vkpt::SceneOptions{}.environmentIntensity),
          Number(&O::envIntensity, SettingRange("environment_intensity"))),
      Row({"--exposure"}, "STOPS", "PNG only: multiply radiance by 2^STOPS before the view transform", "0",
          Number(&O::exposure, {-64, 64})),
      Row({"--view"}, "NAME",
          "PNG only: how radiance is shown: `neutral` (Khronos PBR Neutral), `agx` (Blender's AgX), `aces` (Hill's "
          "ACES fit) or `clamp` (clipped at 1)",
          "neutral",
          Choice(&O::view,
                 {{"neutral", View::kNeutral}, {"agx", View::kAgx}, {"aces", View::kAces}, {"clamp", View::kClamp}})),
      Row({"--variant"}, "NAME|INDEX", "render the materials of this KHR_materials_variants variant (-v lists them)",
          "none", Text(&O::variant, "a variant name or index")),
      Row({"--animation"}, "NAME|INDEX", "pose the scene by this glTF animation (-v lists them)",
          "none: the nodes' own transforms", Text(&O::animation, "an animation name or index")),
      Row({"--at"}, "SECONDS", "time in the `--animation` at which the scene is posed", "0",
          Number(&O::at, SettingRange("time"))),
      Row({"--frames"}, "FIRST:LAST[:STEP]",
          "render a sequence from one load: frame k at k / `--fps` s into the `--animation`, turned by k × `--orbit`, "
          "written to `--out` with the frame number (`NAME.####.EXT`, or in place of a run of `#`)",
          "one image", FramesValue()),
      Row({"--fps"}, "N", "frames per second of `--frames`", "24", Number(&O::fps, {0.0, 1e6, true})),
      Row({"--texture-lod"}, "MODE",
          "mip levels of colour textures after the camera's hit: by each path's ray cone, or level 0 everywhere",
          "cones", Choice(&O::textureLod, {{"cones", true}, {"none", false}})),
      Row({"--light-sampler"}, "MODE",
          "how light sampling chooses among emissive triangles, point and spot lights: `tree` (by how much each may "
          "light the shading point: a light tree), `power` (by power alone) or `auto` (the tree from 8 such lights on)",
          "auto", Choice(&O::lightSampler, LightSamplerChoices())),
      Row({"--leaf-size"}, "N", "maximum triangles per BVH leaf", "8", Number(&O::leafSize, {1, 15})),
      Row({"--splits"}, "MODE",
          "how the BVH divides the scene: `object`, `spatial` (SBVH) or `auto` (the lower SAH cost)", "auto",
          Choice(&O::splits,
                 {{"auto", SplitMode::kAuto}, {"object", SplitMode::kObject}, {"spatial", SplitMode::kSpatial}})),
      Row({"--max-memory"}, "SIZE",
          "host memory a scene may need, checked before it is read (bytes, or `K`/`M`/`G`/`T`)", "half of physical RAM",
          MaxMemoryValue()),
      Row({"--max-texels"}, "N",
          "texels the scene's texture images may have, checked from their headers (or `K`/`M`/`G`)", "256M",
          MaxTexelsValue()),
      Row({"--allow-external-uris"}, "", "let a glTF read files outside its own folder", "off",
          AllowExternalUrisValue()),
  };
}

// What vkpt reports, and the options that only print.
std::vector<OptionDef> ReportRows() {
  return {
      Row({"--stats"}, "FILE", "after the image, write the run as one JSON object (schema in docs/stats.md)", "",
          Text(&O::stats, "a file name")),
      Row({"-v", "--verbose"}, "", "print what was loaded, warnings, ignored glTF features and a line per pass", "",
          Flag(&O::verbose)),
      Row({"-h", "--help"}, "", "print the help and exit", "", NoStats(Flag(&O::help))),
      Row({"--version"}, "", "print the version and exit", "", NoStats(Flag(&O::version))),
  };
}

std::string WithoutBackticks(std::string s) {
  s.erase(std::remove(s.begin(), s.end(), '`'), s.end());
  return s;
}

// " s " with every "|" escaped, " " if s is empty.
std::string MarkdownCell(const std::string& s) {
  std::string cell = " ";
  for (char c : s) cell += c == '|' ? std::string("\\|") : std::string(1, c);
  return s.empty() ? cell : cell + " ";
}

// `text` wrapped to `width` columns, every line after the first indented by `indent`.
std::string Wrap(const std::string& text, size_t firstColumn, size_t indent, size_t width) {
  std::istringstream words(text);
  std::string out, word;
  size_t column = firstColumn;
  bool first = true;
  while (words >> word) {
    if (!first && column + 1 + word.size() > width) {
      out += "\n" + std::string(indent, ' ');
      column = indent;
    } else if (!first) {
      out += ' ';
      ++column;
    }
    out += word;
    column += word.size();
    first = false;
  }
  return out;
}

}  // namespace

size_t OptionDef::Arity() const {
  if (value.empty()) return 0;
  return size_t(std::count(value.begin(), value.end(), ' ')) + 1;
}

std::string OptionDef::LongName() const { return names.back(); }

std::string OptionDef::StatsKey() const {
  std::string key = LongName().substr(2);
  std::replace(key.begin(), key.end(), '-', '_');
  return key;
}

std::string OptionDef::Synopsis() const {
  std::string s;
  for (const std::string& name : names) s += (s.empty() ? "" : ", ") + name;
  return value.empty() ? s : s + " " + value;
}

const std::vector<OptionDef>& OptionTable() {
  static const std::vector<OptionDef> table = [] {
    std::vector<OptionDef> rows = RenderRows();
    for (auto part : {DeviceRows, CameraRows, SceneRows, ReportRows})
      for (OptionDef& row : part()) rows.push_back(std::move(row));
    return rows;
  }();
  return table;
}

const OptionDef* FindOption(const std::string& name) {
  for (const OptionDef& def : OptionTable())
    if (std::find(def.names.begin(), def.names.end(), name) != def.names.end()) return &def;
  return nullptr;
}

// (Built by appends: GCC 12 sees a false -Wrestrict, PR 105651, in "literal" + string.)
std::string OptionTableMarkdown() {
  std::string md = "| option | meaning | values | default |\n|---|---|---|---|\n";
  for (const OptionDef& def : OptionTable()) {
    std::string names;
    for (const std::string& name : def.names) {
      names.append(names.empty() ? "`" : ", `").append(name);
      if (&name == &def.names.back() && !def.value.empty()) names.append(" ").append(def.value);
      names.append("`");
    }
    md.append("|");
    for (const std::string* cell :
         std::initializer_list<const std::string*>{&names, &def.meaning, &def.how.accepts, &def.defaultText})
      md.append(MarkdownCell(*cell)).append("|");
    md.append("\n");
  }
  return md;
}

std::string OptionHelpLines() {
  constexpr size_t kIndent = 21, kWidth = 92;
  std::string help;
  for (const OptionDef& def : OptionTable()) {
    std::string text = def.meaning, accepts = def.how.accepts;
    // A range is not broken across lines: its spaces are \x1f until wrapped.
    if (!accepts.empty() && (accepts[0] == '[' || accepts[0] == '('))
      std::replace(accepts.begin(), accepts.end(), ' ', '\x1f');
    if (!accepts.empty()) text += " (values: " + accepts + ")";
    if (!def.defaultText.empty()) text += " [default: " + def.defaultText + "]";
    std::string left = "  " + def.Synopsis();
    left += left.size() < kIndent ? std::string(kIndent - left.size(), ' ') : "\n" + std::string(kIndent, ' ');
    std::string wrapped = Wrap(WithoutBackticks(text), kIndent, kIndent, kWidth);
    std::replace(wrapped.begin(), wrapped.end(), '\x1f', ' ');
    help += left + wrapped + "\n";
  }
  return help;
}

}  // namespace vkpt::internal

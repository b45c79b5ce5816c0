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
using S = vkpt::SceneOptions;
using C = vkpt::Camera;
using R = vkpt::RenderOptions;

// The row of a setting of the library's schema (vkpt/settings_schema.h): its flag and
// meaning are the schema's, to which `more` adds what only the command line does.
OptionDef SettingRow(const std::string& key, std::string value, const std::string& more, std::string defaultText,
                     OptionValue how) {
  const Setting& s = SettingOf(key);
  return Row({s.flag}, std::move(value), s.doc + more, std::move(defaultText), std::move(how));
}
OptionDef SettingRow(const std::string& key, std::string value, std::string defaultText, OptionValue how) {
  return SettingRow(key, std::move(value), "", std::move(defaultText), std::move(how));
}

// The defaults shown are the library's own (vkpt/vkpt.h), which are the command line's.
const vkpt::RenderOptions kRender;

// The image, its samples and how they are taken.
std::vector<OptionDef> RenderRows() {
  return {
      Row({"--scene"}, "FILE", "glTF 2.0 scene to render, `.gltf` or `.glb` (required)", "", Text(Own(&O::scene))),
      Row({"--out"}, "FILE", "output image: `.png` (8-bit sRGB), `.pfm` or `.exr` (linear float), written atomically",
          "`<scene name>.png`", OutValue()),
      SettingRow("width", "N", "512", Number(Api(kRenderPart, &R::width), SettingRange("width"))),
      SettingRow("height", "N", "from the camera's aspect ratio, else 512",
                 Number(Api(kRenderPart, &R::height), SettingRange("height"))),
      SettingRow("spp", "N",
                 FormatNumber(kDefaultSpp) + "; " + FormatNumber(kBudgetMaxSpp) + " with `--time` or `--noise-target`",
                 SppValue()),
      SettingRow("seconds", "SECONDS", "none", Number(Api(kRenderPart, &R::seconds), SettingRange("seconds"))),
      SettingRow("noise_target", "X", "none", Number(Api(kRenderPart, &R::noiseTarget), SettingRange("noise_target"))),
      Row({"--adaptive"}, "",
          "adaptive sampling: a pixel stops once its and its neighbours' estimated error is below `--noise-target`",
          "on with `--noise-target`", AdaptiveValue(true)),
      Row({"--no-adaptive"}, "", "every pixel takes samples until the render stops", "", AdaptiveValue(false)),
      SettingRow("aovs", "LIST", ", written in layers of an `.exr` `--out`, else to files beside it", "none",
                 AovValue()),
      SettingRow("denoise", "", ": `--out` denoised, the raw image beside it as `NAME.raw.EXT`", "off",
                 Flag(Api(kRenderPart, &R::denoise))),
      Row({"--checkpoint"}, "SECONDS", "rewrite `--out` every SECONDS during the render, with the samples so far",
          "none", CheckpointValue()),
      SettingRow("seed", "N", FormatNumber(kRender.seed), Number(Api(kRenderPart, &R::seed), SettingRange("seed"))),
      SettingRow("chunk_spp", "N", FormatNumber(kRender.chunkSpp),
                 Number(Api(kRenderPart, &R::chunkSpp), SettingRange("chunk_spp"))),
      SettingRow("max_depth", "N", FormatNumber(kRender.maxDepth),
                 Number(Api(kRenderPart, &R::maxDepth), SettingRange("max_depth"))),
      SettingRow("rr_depth", "N", FormatNumber(kRender.rrDepth),
                 Number(Api(kRenderPart, &R::rrDepth), SettingRange("rr_depth"))),
  };
}

// Which renderer and device, and the modes that compare instead of render.
std::vector<OptionDef> DeviceRows() {
  return {
      SettingRow("backend", "NAME", "auto", Choice(Api(kScenePart, &S::backend), BackendChoices())),
      SettingRow("device", "N|NAME", "discrete > integrated > virtual > CPU",
                 Text(Api(kScenePart, &S::device), "a device index or name")),
      Row({"--list-devices"}, "", "list Vulkan devices and exit", "", NoStats(Flag(Own(&O::listDevices)))),
      SettingRow("validation", "", "off", Flag(Api(kScenePart, &S::validation))),
      SettingRow("batch", "N", "about 2^20 paths per submission",
                 Number(Api(kRenderPart, &R::batch), SettingRange("batch"))),
      SettingRow("threads", "N", "all cores", Number(Api(kScenePart, &S::threads), SettingRange("threads"))),
      Row({"--interactive"}, "",
          "open a window showing the render as it accumulates; move the camera with the mouse and keys, P saves "
          "(docs/viewer.md)",
          "", NoStats(Flag(Own(&O::interactive)))),
      Row({"--compare"}, "", "render on the CPU and on Vulkan with the same seed and report how they agree", "",
          Flag(Own(&O::compare))),
      Row({"--diff"}, "A B", "compare two `.pfm` images without rendering; heat map to `--out` if given", "",
          DiffValue()),
  };
}

// Where the camera stands and looks.
std::vector<OptionDef> CameraRows() {
  return {
      SettingRow("index", "N", "0", Number(Api(kCameraPart, &C::index), SettingRange("index"))),
      SettingRow("look_from", "X,Y,Z", "the camera's position",
                 PointValue(Api(kCameraPart, &C::lookFrom), "look_from")),
      SettingRow("look_at", "X,Y,Z", "the scene's centre with `--look-from`, else straight ahead",
                 PointValue(Api(kCameraPart, &C::lookAt), "look_at")),
      SettingRow("up", "X,Y,Z", "+Y, glTF's up", PointValue(Api(kCameraPart, &C::up), "up")),
      SettingRow("fov", "DEGREES", "the camera's", Number(Api(kCameraPart, &C::fovDegrees), SettingRange("fov"))),
      SettingRow("orbit", "DEGREES", FormatNumber(vkpt::Camera{}.orbitDegrees),
                 Number(Api(kCameraPart, &C::orbitDegrees), SettingRange("orbit"))),
  };
}

// The scene as rendered and its limits.
std::vector<OptionDef> SceneRows() {
  return {
      SettingRow("background", "R,G,B", " (one number: grey)",
                 "the studio environment if the scene has no lights, else 0", BackgroundValue()),
      SettingRow("environment", "FILE", "none", Text(Api(kScenePart, &S::environment), "an .hdr or .exr file")),
      SettingRow("environment_rotation", "DEGREES", "0",
                 Number(Api(kRenderPart, &R::environmentRotation), SettingRange("environment_rotation"))),
      SettingRow("environment_intensity", "X", FormatNumber(vkpt::SceneOptions{}.environmentIntensity),
                 Number(Api(kScenePart, &S::environmentIntensity), SettingRange("environment_intensity"))),
      Row({"--exposure"}, "STOPS", "PNG only: multiply radiance by 2^STOPS before the view transform", "0",
          Number(Own(&O::exposure), {-64, 64})),
      Row({"--view"}, "NAME",
          "PNG only: how radiance is shown: `neutral` (Khronos PBR Neutral), `agx` (Blender's AgX), `aces` (Hill's "
          "ACES fit) or `clamp` (clipped at 1)",
          "neutral",
          Choice(Own(&O::view),
                 {{"neutral", View::kNeutral}, {"agx", View::kAgx}, {"aces", View::kAces}, {"clamp", View::kClamp}})),
      SettingRow("variant", "NAME|INDEX", " (-v lists them)", "none",
                 Text(Api(kScenePart, &S::variant), "a variant name or index")),
      SettingRow("animation", "NAME|INDEX", " (-v lists them)", "none: the nodes' own transforms",
                 Text(Api(kScenePart, &S::animation), "an animation name or index")),
      SettingRow("time", "SECONDS", "0", Number(Api(kRenderPart, &R::time), SettingRange("time"))),
      Row({"--frames"}, "FIRST:LAST[:STEP]",
          "render a sequence from one load: frame k at k / `--fps` s into the `--animation`, turned by k × `--orbit`, "
          "written to `--out` with the frame number (`NAME.####.EXT`, or in place of a run of `#`)",
          "one image", FramesValue()),
      Row({"--fps"}, "N", "frames per second of `--frames`", "24", Number(Own(&O::fps), {0.0, 1e6, true})),
      SettingRow("texture_lod", "MODE", "cones",
                 Choice(Api(kRenderPart, &R::textureLod), {{"cones", true}, {"none", false}})),
      SettingRow("light_sampler", "MODE", "auto", Choice(Api(kScenePart, &S::lightSampler), LightSamplerChoices())),
      Row({"--leaf-size"}, "N", "maximum triangles per BVH leaf", "8", Number(Own(&O::leafSize), {1, 15})),
      Row({"--splits"}, "MODE",
          "how the BVH divides the scene: `object`, `spatial` (SBVH) or `auto` (the lower SAH cost)", "auto",
          Choice(Own(&O::splits),
                 {{"auto", SplitMode::kAuto}, {"object", SplitMode::kObject}, {"spatial", SplitMode::kSpatial}})),
      SettingRow("max_memory", "SIZE", " (bytes, or `K`/`M`/`G`/`T`)", "half of physical RAM", MaxMemoryValue()),
      SettingRow("max_texels", "N", " (or `K`/`M`/`G`)", "256M", MaxTexelsValue()),
      SettingRow("allow_external_uris", "", "off", AllowExternalUrisValue()),
  };
}

// What vkpt reports, and the options that only print.
std::vector<OptionDef> ReportRows() {
  return {
      Row({"--stats"}, "FILE", "after the image, write the run as one JSON object (schema in docs/stats.md)", "",
          Text(Own(&O::stats), "a file name")),
      Row({"-v", "--verbose"}, "", "print what was loaded, warnings, ignored glTF features and a line per pass", "",
          Flag(Own(&O::verbose))),
      Row({"-h", "--help"}, "", "print the help and exit", "", NoStats(Flag(Own(&O::help)))),
      Row({"--version"}, "", "print the version and exit", "", NoStats(Flag(Own(&O::version)))),
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

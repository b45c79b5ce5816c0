#include "app/options.h"

#include <cstdlib>

#include "app/option_table.h"
#include "session/budget.h"

namespace vkpt::internal {
namespace {

// The options table (app/option_table.cpp) between these two.
constexpr const char* kHelpHead = R"(usage: vkpt --scene FILE [options]
       vkpt --scene FILE --interactive [options]
       vkpt --diff A.pfm B.pfm [--out heatmap.png]
       vkpt --list-devices

Renders a glTF 2.0 scene (.gltf or .glb) by Monte Carlo path tracing. Every option
in full: docs/options.md.

)";

constexpr const char* kHelpTail = R"(
SIGINT or SIGTERM during the render stops it after the current pass (about a second)
and writes the image of the samples taken; a second one exits at once.

Under mpirun (built with MPI: see --version), the processes share one frame by chunks
and rank 0 writes the image, bit-identical to one process's (docs/mpi.md).

Exit status: 0 success, 1 error (bad scene, I/O, device), 2 usage error,
3 Vulkan validation messages were reported, 4 --compare/--diff found a disagreement,
130/143 stopped by SIGINT/SIGTERM (the image of the samples taken was written).
)";

// --interactive: one view, accumulating in a window on a display.
void CheckInteractive(const Options& o) {
  const vkpt::RenderOptions& r = o.api.render;
  if (o.frames || o.compare || r.seconds || r.noiseTarget || r.adaptive || o.checkpoint > 0.0 || !r.aovs.empty() ||
      r.denoise)
    throw UsageError(
        "--interactive shows one view in a window as it accumulates; it takes no --frames, --compare, --time, "
        "--noise-target, --adaptive, --checkpoint, --aov or --denoise");
}

// The checks between options, and what follows from them (the --spp bound, --out's name).
void Complete(Options& o) {
  if (o.interactive) CheckInteractive(o);
  if (o.compare && o.api.scene.backend != vkpt::Backend::Auto)
    throw UsageError("--compare uses both backends; drop --backend");
  if (o.compare && (o.api.render.seconds || o.api.render.noiseTarget || o.Budget().adaptive))
    throw UsageError(
        "--compare renders both backends with the same samples; it takes no --time, --noise-target or --adaptive");
  if (o.compare && (!o.api.render.aovs.empty() || o.api.render.denoise))
    throw UsageError("--compare checks the backends against each other; it takes no --aov or --denoise");
  if (o.scene.empty()) throw UsageError("--scene FILE is required (see --help)");
  if (o.frames && o.api.render.time.value_or(0.0) != 0.0)
    throw UsageError("--frames gives each frame its time (k / --fps); drop --at");
  if (o.frames && o.compare) throw UsageError("--compare checks one image; drop --frames");
  try {
    CheckSettings(o.api);  // the library's own checks
  } catch (const SettingError& e) {
    throw UsageError(e.what());
  }
  if (o.out.empty()) {
    std::string base = o.scene.substr(o.scene.find_last_of('/') + 1);
    o.out = base.substr(0, base.find_last_of('.')) + ".png";
  }
  if (o.stats == o.out) throw UsageError("--stats and --out name the same file \"" + o.out + "\"");
  // A command renders what it names: its time and turn are 0 unless it says otherwise.
  o.api.render.time = o.api.render.time.value_or(0.0);
  o.api.render.environmentRotation = o.api.render.environmentRotation.value_or(0.0f);
}

}  // namespace

std::string HelpText() { return kHelpHead + OptionHelpLines() + kHelpTail; }

Options ParseOptions(int argc, const char* const* argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    std::vector<std::string> values;
    const size_t eq = arg.find('=');
    const bool inlineValue = arg.rfind("--", 0) == 0 && eq != std::string::npos;
    if (inlineValue) {
      values.push_back(arg.substr(eq + 1));
      arg = arg.substr(0, eq);
    }
    const OptionDef* def = FindOption(arg);
    if (!def) throw UsageError("unknown option \"" + arg + "\" (see --help)");
    const size_t arity = def->Arity();
    if (inlineValue && arity == 0) throw UsageError(arg + " takes no value, got \"" + arg + "=" + values[0] + "\"");
    const std::string needs = arg + " needs " + (arity == 1 ? "a value" : "two values") + ": " + def->Synopsis();
    if (inlineValue && arity > 1) throw UsageError(needs);
    while (values.size() < arity) {
      if (i + 1 >= argc) throw UsageError(needs);
      values.push_back(argv[++i]);
    }
    def->how.set(o, GivenOption{arg, values});
    o.given.emplace_back(def->LongName(), values);
  }
  if (const char* env = std::getenv("VKPT_VALIDATION"); env && std::string(env) == "1") o.api.scene.validation = true;
  if (o.help || o.version || o.listDevices) return o;
  if (!o.diff.empty()) {
    if (!o.scene.empty() || o.compare || !o.stats.empty())
      throw UsageError("--diff compares two images; it takes no --scene, --compare or --stats");
    return o;
  }
  Complete(o);
  return o;
}

}  // namespace vkpt::internal

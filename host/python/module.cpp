// The Python module vkpt._vkpt, which the package vkpt (python/vkpt/__init__.py) re-exports:
// the library API of vkpt/vkpt.h with images as NumPy arrays (docs/python.md). Renders
// release the GIL; Ctrl-C or an exception from a progress callback cancels a render
// between passes and is raised when it returns.
#include <algorithm>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "python/bindings.h"
#include "vkpt/api_terms.h"
#include "vkpt/setting_choices.h"
#include "vkpt/settings_schema.h"
#include "vkpt/vkpt.h"

namespace py = pybind11;
using namespace pybind11::literals;

namespace vkpt::python {
namespace {

// The keywords' defaults are the library's (vkpt/vkpt.h).
const SceneOptions kScene;
const RenderOptions kRender;

std::unique_ptr<PyScene> OpenScene(const std::filesystem::path& path, const std::string& backend,
                                   const std::string& device, bool validation, unsigned threads, uint64_t maxMemory,
                                   uint64_t maxTexels, bool allowExternalUris, const std::string& variant,
                                   const std::string& animation, const std::string& environment,
                                   float environmentIntensity, const std::string& lightSampler) {
  SceneOptions o;
  o.backend = BackendFrom(backend);
  o.device = device;
  o.validation = validation;
  o.threads = threads;
  o.maxMemory = maxMemory;
  o.maxTexels = maxTexels;
  o.allowExternalUris = allowExternalUris;
  o.variant = variant;
  o.animation = animation;
  o.environment = environment;
  o.environmentIntensity = environmentIntensity;
  o.lightSampler = LightSamplerFrom(lightSampler);
  o.log = ToLogging;
  py::gil_scoped_release released;
  return std::make_unique<PyScene>(Scene(path.string(), o));
}

// Scene.render and Scene.begin: the render keywords as RenderOptions, given to `Run`.
template <class Result, Result (*Run)(PyScene&, const py::object&, RenderOptions, const py::object&)>
Result With(PyScene& self, const py::object& camera, std::optional<uint32_t> width, std::optional<uint32_t> height,
            std::optional<uint32_t> spp, std::optional<double> seconds, std::optional<double> noiseTarget,
            std::optional<bool> adaptive, uint32_t seed, uint32_t maxDepth, uint32_t rrDepth, uint32_t chunkSpp,
            uint32_t batch, std::optional<double> time, std::optional<std::array<float, 3>> background,
            std::optional<float> environmentRotation, bool textureLod, std::vector<std::string> aovs, bool denoise,
            const py::object& progress) {
  RenderOptions o;
  o.width = width;
  o.height = height;
  o.spp = spp;
  o.seconds = seconds;
  o.noiseTarget = noiseTarget;
  o.adaptive = adaptive;
  o.seed = seed;
  o.maxDepth = maxDepth;
  o.rrDepth = rrDepth;
  o.chunkSpp = chunkSpp;
  o.batch = batch;
  o.time = time;
  o.background = background;
  o.environmentRotation = environmentRotation;
  o.textureLod = textureLod;
  o.aovs = std::move(aovs);
  o.denoise = denoise;
  return Run(self, camera, std::move(o), progress);
}

// Defines Scene.`name` with the render keywords, their defaults the library's.
template <class F, class... Extra>
void DefWithRenderKeywords(py::class_<PyScene>& scene, const char* name, F f, const char* doc, Extra... extra) {
  scene.def(name, f, "camera"_a = py::none(), py::kw_only(), "width"_a = py::none(), "height"_a = py::none(),
            "spp"_a = py::none(), "seconds"_a = py::none(), "noise_target"_a = py::none(), "adaptive"_a = py::none(),
            "seed"_a = kRender.seed, "max_depth"_a = kRender.maxDepth, "rr_depth"_a = kRender.rrDepth,
            "chunk_spp"_a = kRender.chunkSpp, "batch"_a = kRender.batch, "time"_a = py::none(),
            "background"_a = py::none(), "environment_rotation"_a = py::none(), "texture_lod"_a = kRender.textureLod,
            "aovs"_a = kRender.aovs, "denoise"_a = kRender.denoise, "progress"_a = py::none(), doc, extra...);
}

// The signatures pybind11 puts above each docstring show the keywords and their defaults;
// the lines below them what each keyword does (KeywordDocs).
void BindScene(py::module_& m) {
  const std::string sceneDoc = R"(A glTF 2.0 scene loaded once and rendered any number of times.

Raises vkpt.Error naming the file and the problem, vkpt.SettingError for a setting out
of its range.

)" + KeywordDocs("SceneOptions::");
  const std::string renderDoc = R"(Renders a view and returns a vkpt.Render (np.asarray(render) is the image).

camera: None (the file's first camera), an int (the file's camera of that index) or a
vkpt.Camera. The GIL is released while rendering; progress(fraction) is called now and
then, and returning False ends the render at its next pass with what it has (stopped_by
"cancelled"), as Scene.cancel() from another thread does. aovs: albedo, normal, depth,
position, variance, spp, heatmap, object_id, material_id, instance_id, or "all". A
setting out of its range raises vkpt.SettingError.

)" + KeywordDocs("RenderOptions::");
  const std::string beginDoc = R"(Begins a render taken in steps and returns a vkpt.ProgressiveRender.

Its keywords are render's: the camera and the image as there; it takes the samples its
advance() asks for, up to spp (None: 65536), so seconds, noise_target and adaptive raise
vkpt.SettingError. progress(fraction of spp) is called during each advance, whose Ctrl-C,
exception, False or Scene.cancel() end that step. It ends the progressive render begun
before, as render and update do.
)";
  py::class_<PyScene> scene(m, "Scene", sceneDoc.c_str());
  BindSceneState(scene);
  scene.def(py::init(&OpenScene), "path"_a, py::kw_only(),
            "backend"_a = internal::ChoiceName(internal::BackendChoices(), kScene.backend), "device"_a = kScene.device,
            "validation"_a = kScene.validation, "threads"_a = kScene.threads, "max_memory"_a = kScene.maxMemory,
            "max_texels"_a = kScene.maxTexels, "allow_external_uris"_a = kScene.allowExternalUris,
            "variant"_a = kScene.variant, "animation"_a = kScene.animation, "environment"_a = kScene.environment,
            "environment_intensity"_a = kScene.environmentIntensity,
            "light_sampler"_a = internal::ChoiceName(internal::LightSamplerChoices(), kScene.lightSampler));
  DefWithRenderKeywords(scene, "render", &With<PyRender, &RenderOn>, renderDoc.c_str());
  DefWithRenderKeywords(scene, "begin", &With<PyProgressive, &BeginOn>, beginDoc.c_str(), py::keep_alive<0, 1>());
}

}  // namespace

namespace {

// A setting's doc in Python's terms, with its range.
std::string DocOf(const internal::Setting& s) {
  std::string doc = internal::InTerms(s.doc, internal::Terms::kCommandLine, internal::Terms::kPython);
  doc.erase(std::remove(doc.begin(), doc.end(), '`'), doc.end());
  return doc + (s.range ? " (values: " + internal::RangeText(*s.range) + ")" : "");
}

}  // namespace

std::string KeywordDocs(const std::string& part) {
  std::string text;
  for (const internal::Setting& s : internal::Settings())
    if (s.field.rfind(part, 0) == 0) text += s.key + ": " + DocOf(s) + "\n";
  return text;
}

std::string KeywordDoc(const std::string& part, const std::string& key) {
  for (const internal::Setting& s : internal::Settings())
    if (s.field.rfind(part, 0) == 0 && s.key == key) return DocOf(s);
  throw std::logic_error("no setting " + part + key);
}

namespace {

// vkpt._settings(): the settings schema (vkpt/settings_schema.h) for tests that try every
// setting: each one's keyword, where it goes ("scene", "camera" or "render"), its
// command-line option, type, default numbers, doc (in Python's terms) and, for a number,
// its range.
void BindSettings(py::module_& m) {
  m.def("_settings", [] {
    py::list settings;
    for (const internal::Setting& s : internal::Settings()) {
      py::dict d("key"_a = s.key, "flag"_a = s.flag, "field"_a = s.field, "python"_a = s.PythonName(),
                 "type"_a = s.type, "default"_a = s.numbers({}),
                 "doc"_a = internal::InTerms(s.doc, internal::Terms::kCommandLine, internal::Terms::kPython));
      d["where"] = s.field.rfind("Scene", 0) == 0 ? "scene" : s.field.rfind("Camera", 0) == 0 ? "camera" : "render";
      if (s.range)
        d["range"] = py::make_tuple(s.range->lo, s.range->hi, s.range->loOpen, internal::RangeText(*s.range));
      settings.append(d);
    }
    return settings;
  });
}

}  // namespace
}  // namespace vkpt::python

PYBIND11_MODULE(_vkpt, m) {
  using namespace vkpt::python;
  m.doc() = "vkpt: a physically based path tracer for glTF 2.0 scenes, on Vulkan or the CPU";
  m.attr("__version__") = VKPT_VERSION;
  // vkpt.Error, with the library's setting names in Python's (vkpt/api_terms.h), and
  // vkpt.SettingError, a setting out of its range: both a vkpt.Error and a ValueError. The
  // types live as long as the interpreter: their handles are never released.
  static const py::handle error = py::exception<vkpt::Error>(m, "Error", PyExc_RuntimeError).release();
  error.attr("__doc__") = "A failure inside vkpt: its message names the file or setting and the problem.";
  py::object setting = py::reinterpret_steal<py::object>(PyErr_NewExceptionWithDoc(
      "vkpt.SettingError",
      "A setting out of the range the command line allows, or at odds with another: both a vkpt.Error and a "
      "ValueError.",
      py::make_tuple(error, py::handle(PyExc_ValueError)).ptr(), nullptr));
  if (!setting) throw py::error_already_set();
  m.attr("SettingError") = setting;
  static const py::handle settingError = setting.release();
  py::register_exception_translator([](std::exception_ptr p) {
    using vkpt::internal::InTerms;
    using vkpt::internal::Terms;
    try {
      if (p) std::rethrow_exception(p);
    } catch (const vkpt::SettingError& e) {
      PyErr_SetString(settingError.ptr(), InTerms(e.what(), Terms::kCpp, Terms::kPython).c_str());
    } catch (const vkpt::Error& e) {
      PyErr_SetString(error.ptr(), InTerms(e.what(), Terms::kCpp, Terms::kPython).c_str());
    }
  });
  BindSettings(m);
  BindCamera(m);
  BindRender(m);
  BindSceneInfo(m);
  BindProgressive(m);  // after the records and before the Scene: their names in its signatures
  BindScene(m);
  BindDevices(m);
}

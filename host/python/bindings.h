// The pieces of the Python module (module.cpp): the Scene as Python holds it, option values
// from Python objects, the Camera type, a render's result whose images are NumPy arrays, the
// scene's records and parameters, and the library's log as Python's logging.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "vkpt/vkpt.h"

namespace vkpt::python {

namespace py = pybind11;

// A Scene for Python: renders on one Scene are serialised, as the library requires (Python
// threads may call render at once, the GIL being released while it runs).
// Scene.close() releases it (its device and memory): then every use raises vkpt.Error.
struct PyScene {
  explicit PyScene(Scene s) : scene(std::move(s)) {}
  Scene& Get() {
    if (!scene) throw Error("the scene is closed");
    return *scene;
  }
  std::optional<Scene> scene;
  std::mutex rendering;
  std::atomic<bool> cancelled{false};  // Scene.cancel() during the render running now
};

// `f()` with the GIL released and the scene's renders serialised.
template <class F>
auto Serialised(PyScene& scene, F&& f) {
  py::gil_scoped_release released;
  std::lock_guard<std::mutex> lock(scene.rendering);
  return f();
}

// A message of the library (SceneOptions::log) to Python's logging, logger "vkpt".
void ToLogging(LogLevel level, const std::string& message);

// vkpt.Scene's records, parameters, cancel, close and repr (scene_state.cpp).
void BindSceneState(py::class_<PyScene>& scene);

// A name of vkpt/setting_choices.h's BackendChoices; vkpt.SettingError (a ValueError) else.
Backend BackendFrom(const std::string& name);

// A name of LightSamplerChoices; vkpt.SettingError (a ValueError) else.
LightSampler LightSamplerFrom(const std::string& name);

// None (the file's first camera), an int (the file's camera of that index) or a
// vkpt.Camera; TypeError for anything else.
Camera CameraFrom(const py::object& camera);

// The keywords of one part of the settings schema (vkpt/settings_schema.h) for a
// docstring, one line each: "max_depth: maximum number of bounces … [0, 1024]", each
// setting's own doc in Python's terms. `part`: "SceneOptions::", "Camera::" or
// "RenderOptions::".
std::string KeywordDocs(const std::string& part);
// One of them: the doc of keyword `key` of `part`.
std::string KeywordDoc(const std::string& part, const std::string& key);

// vkpt.Camera: keyword construction, fields read and written as Python values; the matrix
// as a 4 × 4 NumPy array M with M @ (x, y, z, 1) in world space.
void BindCamera(py::module_& m);

// vkpt.Render: one render's images and figures. Its arrays are float32 views of the
// result's memory (H × W × C, row 0 at the top), which they keep alive.
class PyRender {
 public:
  explicit PyRender(std::shared_ptr<RenderResult> result) : result_(std::move(result)) {}
  py::array ImageArray() const;
  py::object RawArray() const;  // None without denoise
  py::dict AovArrays() const;   // name → array
  py::dict Channels() const;    // name → channel names ("image", "raw" and each AOV)
  const RenderResult& Result() const { return *result_; }

 private:
  py::array View(Image& image) const;
  std::shared_ptr<RenderResult> result_;
};

// One render's callbacks into Python, from the rendering thread: each takes the GIL (the
// progress hook is set only when there is a callback to call). The first exception
// (KeyboardInterrupt from Ctrl-C, or one the progress callback raised) cancels the render
// and is raised once it has returned; progress returning False, or Scene.cancel(), cancels
// it and the render so far is returned.
class Callbacks {
 public:
  Callbacks(py::object progress, const std::atomic<bool>& cancelled)
      : progress_(std::move(progress)), cancelled_(cancelled) {}

  // A render's callbacks on `scene`, hooked on `options` weakly: the options may outlive
  // them (a progressive render's stay with its scene) and must not drop a Python object
  // without the GIL.
  static std::shared_ptr<Callbacks> Hook(PyScene& scene, const py::object& progress, RenderOptions& options) {
    auto callbacks = std::make_shared<Callbacks>(progress, scene.cancelled);
    const std::weak_ptr<Callbacks> weak = callbacks;
    if (!progress.is_none())
      options.progress = [weak](double f) {
        if (const auto c = weak.lock()) c->Progress(f);
      };
    options.cancel = [weak] {
      const auto c = weak.lock();
      return !c || c->Cancel();
    };
    return callbacks;
  }

  // A new step of a progressive render: progress's False stopped the last one alone.
  void Rearm() { stopped_ = false; }

  void Progress(double fraction) {
    py::gil_scoped_acquire gil;
    if (error_ || stopped_) return;
    try {
      stopped_ = progress_(fraction).ptr() == Py_False;
    } catch (py::error_already_set& e) {
      error_.emplace(std::move(e));
    }
  }

  bool Cancel() {
    if (cancelled_) return true;
    py::gil_scoped_acquire gil;
    if (!error_ && PyErr_CheckSignals() != 0) error_.emplace();  // takes the pending exception
    return error_.has_value() || stopped_;
  }

  void RaiseAny() {
    if (error_) {
      py::error_already_set e = std::move(*error_);
      error_.reset();
      throw e;
    }
  }

 private:
  py::object progress_;
  const std::atomic<bool>& cancelled_;
  std::optional<py::error_already_set> error_;
  bool stopped_ = false;  // progress returned False
};

// Renders a view of the scene, the GIL released; Ctrl-C, an exception from `progress`,
// `progress` returning False or Scene.cancel() end it at its next pass.
PyRender RenderOn(PyScene& self, const py::object& camera, RenderOptions options, const py::object& progress);

void BindRender(py::module_& m);

// vkpt.ProgressiveRender (vkpt::ProgressiveRender): steps of samples, each with the GIL
// released and the scene's renders serialised; Ctrl-C, an exception from `progress`,
// `progress` returning False or Scene.cancel() end a step at its next pass.
class PyProgressive {
 public:
  PyProgressive(PyScene& scene, ProgressiveRender render, std::shared_ptr<Callbacks> callbacks)
      : scene_(scene), render_(std::move(render)), callbacks_(std::move(callbacks)) {}
  uint32_t Advance(uint32_t spp);
  PyRender Result();
  ProgressiveRender& Get() { return render_; }

 private:
  PyScene& scene_;  // kept alive by the Python object (Scene.begin's keep_alive)
  ProgressiveRender render_;
  std::shared_ptr<Callbacks> callbacks_;
};

// Begins a progressive render of the scene (Scene.begin).
PyProgressive BeginOn(PyScene& self, const py::object& camera, RenderOptions options, const py::object& progress);

void BindProgressive(py::module_& m);

// vkpt.devices() and vkpt.Device (vkpt::Devices).
void BindDevices(py::module_& m);

// The records a Scene's properties return (include/vkpt/scene_info.h).
void BindSceneInfo(py::module_& m);

}  // namespace vkpt::python

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

// Renders a view of the scene, the GIL released; Ctrl-C, an exception from `progress`,
// `progress` returning False or Scene.cancel() end it at its next pass.
PyRender RenderOn(PyScene& self, const py::object& camera, RenderOptions options, const py::object& progress);

void BindRender(py::module_& m);

// vkpt.devices() and vkpt.Device (vkpt::Devices).
void BindDevices(py::module_& m);

// The records a Scene's properties return (include/vkpt/scene_info.h).
void BindSceneInfo(py::module_& m);

}  // namespace vkpt::python

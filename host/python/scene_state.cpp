// What a vkpt.Scene says and does beside rendering: its records, its parameters
// (vkpt::ParameterMap in Python's types), cancel and close; and the library's log as
// Python's logging.
#include <mutex>
#include <string>
#include <type_traits>
#include <vector>

#include <pybind11/stl.h>

#include "python/bindings.h"
#include "vkpt/api_terms.h"

namespace vkpt::python {

using namespace pybind11::literals;
namespace {

// Waits for a render of the scene on another thread (the GIL released meanwhile).
template <class F>
auto WhenIdle(PyScene& self, F&& f) {
  py::gil_scoped_release released;
  std::lock_guard<std::mutex> lock(self.rendering);
  return f();
}

py::dict ParametersOf(PyScene& self) {
  py::dict d;
  for (const auto& [key, value] : WhenIdle(self, [&] { return self.Get().Parameters(); }))
    d[py::str(key)] = std::visit(
        [](const auto& v) -> py::object {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, Vec3>) return py::make_tuple(v[0], v[1], v[2]);
          else if constexpr (std::is_same_v<T, Quat>) return py::make_tuple(v[0], v[1], v[2], v[3]);
          else return py::cast(v);
        },
        value);
  return d;
}

// `n` Python numbers as floats; TypeError naming `key` else.
template <size_t N>
std::array<float, N> Numbers(const std::string& key, const py::sequence& s) {
  std::array<float, N> out;
  for (size_t c = 0; c < N; ++c) {
    if (!py::isinstance<py::float_>(s[c]) && !py::isinstance<py::int_>(s[c]))
      throw py::type_error(key + ": " + std::to_string(N) + " numbers, not a " +
                           std::string(py::str(s[c].get_type().attr("__name__"))));
    out[c] = s[c].cast<float>();
  }
  return out;
}

// A Python number, bool, sequence of 3 or 4 numbers or str as a parameter's value;
// TypeError else.
ParameterValue ParameterFrom(const std::string& key, const py::handle& value) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value)) return value.cast<double>();
  if (py::isinstance<py::sequence>(value) && !py::isinstance<py::str>(value)) {
    const py::sequence s = value.cast<py::sequence>();
    if (py::len(s) == 3) return Numbers<3>(key, s);
    if (py::len(s) == 4) return Numbers<4>(key, s);
  }
  throw py::type_error(key + ": a parameter is a number, a bool, 3 or 4 numbers, or a str, not " +
                       std::string(py::str(value.get_type().attr("__name__"))));
}

void UpdateFrom(PyScene& self, const py::dict& changes) {
  ParameterMap map;
  for (const auto& [key, value] : changes) {
    const std::string k = py::str(key);
    map[k] = ParameterFrom(k, value);
  }
  WhenIdle(self, [&] { self.Get().Update(map); });
}

void Close(PyScene& self) {
  py::gil_scoped_release released;
  std::lock_guard<std::mutex> lock(self.rendering);
  self.scene.reset();
}

// "<vkpt.Scene 'scenes/cornell.gltf' on cpu: 32 triangles, 5 materials>", or "<vkpt.Scene closed>"
std::string Describe(PyScene& self) {
  if (!self.scene) return "<vkpt.Scene closed>";
  const SceneStats stats = self.scene->Stats();
  return "<vkpt.Scene " + std::string(py::repr(py::str(stats.path))) + " on " + self.scene->Device() + ": " +
         std::to_string(stats.triangles) + " triangles, " + std::to_string(stats.materials) + " materials>";
}

// A getter of one of Scene's lists as a tuple (read-only, as the scene's records are).
template <class T>
auto TupleOf(std::vector<T> (Scene::*list)() const) {
  return [list](PyScene& s) { return py::tuple(py::cast(WhenIdle(s, [&] { return (s.Get().*list)(); }))); };
}

}  // namespace

void BindSceneState(py::class_<PyScene>& scene) {
  scene
      .def_property_readonly(
          "camera_count", [](PyScene& s) { return s.Get().CameraCount(); }, "how many cameras the file has")
      .def_property_readonly(
          "device", [](PyScene& s) { return s.Get().Device(); }, "\"cpu\", or the Vulkan device's name")
      .def_property_readonly("materials", TupleOf(&Scene::Materials),
                             "the file's materials (vkpt.MaterialInfo), vkpt's default last")
      .def_property_readonly("cameras", TupleOf(&Scene::Cameras),
                             "the file's cameras (vkpt.CameraInfo), in scene-graph order")
      .def_property_readonly("lights", TupleOf(&Scene::Lights),
                             "the punctual lights (vkpt.LightInfo), in scene-graph order")
      .def_property_readonly("nodes", TupleOf(&Scene::Nodes), "the file's nodes (vkpt.NodeInfo), by index")
      .def_property_readonly("meshes", TupleOf(&Scene::Meshes), "the file's meshes (vkpt.MeshInfo), by index")
      .def_property_readonly("animations", TupleOf(&Scene::Animations), "the file's animations (vkpt.AnimationInfo)")
      .def_property_readonly("variants", TupleOf(&Scene::Variants), "the KHR_materials_variants names, in index order")
      .def_property_readonly(
          "stats", [](PyScene& s) { return s.Get().Stats(); }, "the scene's counts (vkpt.SceneStats)")
      .def("close", &Close, R"(Releases the scene: its device, buffers and memory (after a render running on
another thread ends). Using it afterwards raises vkpt.Error; closing again does nothing.
A Scene is also a context manager: `with vkpt.Scene(path) as scene:` closes it at the end.)")
      .def(
          "__enter__", [](PyScene& s) -> PyScene& { return s; }, py::return_value_policy::reference)
      .def("__exit__", [](PyScene& s, const py::args&) { Close(s); })
      .def("__repr__", &Describe)
      .def(
          "cancel", [](PyScene& s) { s.cancelled = true; },
          R"(Ends the scene's render running now, on any thread, at its next pass: that render returns
what it has (stopped_by "cancelled"). Renders begun later are not affected.)")
      .def("parameters", &ParametersOf,
           R"(Every editable value of the scene, as a dict from a key to a float, a bool, a
3-tuple (an RGB colour, a vector), a 4-tuple (a quaternion x, y, z, w) or a str:
"materials/<index>/<field>" for each field of vkpt.MaterialInfo that is a factor
("base_color", "roughness", ...); "nodes/<index>/translation", ".../rotation",
".../scale"; "lights/<index>/color", ".../intensity"; "variant" in a file with variants;
"animation" and "time" in a file with animations; "environment/intensity" and
"environment/rotation" with an environment map. Change values and pass the dict (or any
part of it) to update().)")
      .def("update", &UpdateFrom, "changes"_a,
           R"(Applies a dict of parameters() keys to new values. Every value is checked
first: an unknown key, a value of the wrong kind or out of its range raises
vkpt.SettingError, and then nothing changes. The next render does what the change needs
(materials and lights: their arrays alone; nodes, variant, animation: the pose and the
BVH; the file is not read again) and equals, bit for bit, a render of the file so
edited, or loaded with that variant, animation and time.)");
}

// From whichever thread loads or renders. It holds no Python object, so a Scene may
// outlive the interpreter's modules; a failing handler is reported as unraisable, and the
// render goes on.
void ToLogging(LogLevel level, const std::string& message) {
  py::gil_scoped_acquire gil;
  const int python = level == LogLevel::Warning ? 30 : level == LogLevel::Info ? 20 : 10;
  try {
    py::module_::import("logging").attr("getLogger")("vkpt").attr("log")(
        python, internal::InTerms(message, internal::Terms::kCpp, internal::Terms::kPython));
  } catch (py::error_already_set& e) {
    // Ctrl-C arriving while the handler ran: raised again for the render's next cancel check.
    if (e.matches(PyExc_KeyboardInterrupt)) PyErr_SetInterrupt();
    else e.discard_as_unraisable("vkpt's log");
  }
}

}  // namespace vkpt::python

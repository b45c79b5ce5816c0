// Scene.parameters() and Scene.update(): vkpt::ParameterMap in Python's types, and the
// caller's log as Python's logging.
#include <string>
#include <type_traits>

#include "python/bindings.h"
#include "vkpt/api_terms.h"

namespace vkpt::python {
namespace {

// Waits for a render of the scene on another thread (the GIL released meanwhile).
template <class F>
auto WhenIdle(PyScene& self, F&& f) {
  py::gil_scoped_release released;
  std::lock_guard<std::mutex> lock(self.rendering);
  return f();
}

}  // namespace

py::dict ParametersOf(PyScene& self) {
  py::dict d;
  for (const auto& [key, value] : WhenIdle(self, [&] { return self.scene.Parameters(); }))
    d[py::str(key)] = std::visit(
        [](const auto& v) -> py::object {
          if constexpr (std::is_same_v<std::decay_t<decltype(v)>, Rgb>) return py::make_tuple(v[0], v[1], v[2]);
          else return py::cast(v);
        },
        value);
  return d;
}

namespace {

// A Python number, bool or sequence of 3 numbers as a parameter's value; TypeError else.
ParameterValue ParameterFrom(const std::string& key, const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value)) return value.cast<double>();
  if (py::isinstance<py::sequence>(value) && !py::isinstance<py::str>(value) && py::len(value) == 3) {
    const py::sequence s = value.cast<py::sequence>();
    return Rgb{s[0].cast<float>(), s[1].cast<float>(), s[2].cast<float>()};
  }
  throw py::type_error(key + ": a parameter is a number, a bool or 3 numbers, not " +
                       std::string(py::str(value.get_type().attr("__name__"))));
}

}  // namespace

void UpdateFrom(PyScene& self, const py::dict& changes) {
  ParameterMap map;
  for (const auto& [key, value] : changes) {
    const std::string k = py::str(key);
    map[k] = ParameterFrom(k, value);
  }
  WhenIdle(self, [&] { self.scene.Update(map); });
}

// From whichever thread loads or renders. It holds no Python object, so a Scene may outlive the interpreter's
// modules; a failing handler is reported as unraisable, and the render goes on.
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

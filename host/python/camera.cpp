#include <array>
#include <optional>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "python/bindings.h"
#include "vkpt/setting_choices.h"

namespace vkpt::python {

using namespace pybind11::literals;

// A value of the schema's choices, its refusal a vkpt.SettingError (a ValueError).
template <class E>
E ChosenFor(const std::string& key, const internal::Choices<E>& choices, const std::string& name) {
  try {
    return internal::Chosen(key, choices, name);
  } catch (const internal::SettingError& e) {
    throw vkpt::SettingError(e.what());
  }
}

Backend BackendFrom(const std::string& name) { return ChosenFor("backend", internal::BackendChoices(), name); }

LightSampler LightSamplerFrom(const std::string& name) {
  return ChosenFor("light_sampler", internal::LightSamplerChoices(), name);
}

Camera CameraFrom(const py::object& camera) {
  if (camera.is_none()) return Camera{};
  if (py::isinstance<Camera>(camera)) return camera.cast<Camera>();
  if (py::isinstance<py::int_>(camera) && !py::isinstance<py::bool_>(camera)) {
    const long index = camera.cast<long>();
    if (index < 0) throw py::value_error("camera index must be at least 0, got " + std::to_string(index));
    Camera c;
    c.index = uint32_t(index);
    return c;
  }
  throw py::type_error("camera must be None, an int (the file's camera) or a vkpt.Camera, got " +
                       std::string(py::str(py::type::of(camera).attr("__name__"))));
}

namespace {

using Matrix = std::optional<std::array<float, 16>>;

// The glTF column-major values of a 4 × 4 matrix given as rows (NumPy's M[row, column]).
Matrix MatrixFrom(const py::object& value) {
  if (value.is_none()) return std::nullopt;
  const auto m = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!m || m.ndim() != 2 || m.shape(0) != 4 || m.shape(1) != 4)
    throw py::value_error("matrix must be a 4 x 4 array (camera to world, M @ (x, y, z, 1))");
  std::array<float, 16> columns;
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column) columns[column * 4 + row] = m.at(row, column);
  return columns;
}

py::object MatrixArray(const Matrix& matrix) {
  if (!matrix) return py::none();
  py::array_t<float> m({4, 4});
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column) m.mutable_at(row, column) = (*matrix)[column * 4 + row];
  return m;
}

}  // namespace

void BindCamera(py::module_& m) {
  py::class_<Camera>(m, "Camera",
                     (R"(Where a render looks from.

Camera(index=None, *, matrix=None, look_from=None, look_at=None, up=None, fov=None, orbit=0.0)

The file's camera `index` (without cameras: one framing the scene), or its lens placed by
`matrix` (4 x 4, camera to world: the camera looks along its -Z with +Y up); then moved to
look_from, aimed at look_at with `up` up, turned `orbit` degrees about `up` through the
look-at point (or the scene's centre), with a vertical field of view of `fov` degrees.

)" + KeywordDocs("Camera::"))
                         .c_str())
      .def(py::init([](std::optional<uint32_t> index, const py::object& matrix,
                       std::optional<std::array<float, 3>> lookFrom, std::optional<std::array<float, 3>> lookAt,
                       std::optional<std::array<float, 3>> up, std::optional<double> fov, double orbit) {
             Camera c;
             c.index = index;
             c.matrix = MatrixFrom(matrix);
             c.lookFrom = lookFrom;
             c.lookAt = lookAt;
             c.up = up;
             c.fovDegrees = fov;
             c.orbitDegrees = orbit;
             return c;
           }),
           "index"_a = py::none(), py::kw_only(), "matrix"_a = py::none(), "look_from"_a = py::none(),
           "look_at"_a = py::none(), "up"_a = py::none(), "fov"_a = py::none(), "orbit"_a = 0.0)
      .def_readwrite("index", &Camera::index, KeywordDoc("Camera::", "index").c_str())
      .def_property(
          "matrix", [](const Camera& c) { return MatrixArray(c.matrix); },
          [](Camera& c, const py::object& value) { c.matrix = MatrixFrom(value); },
          "camera to world, 4 x 4 (M @ (x, y, z, 1)): the lens placed by it; None: the file's camera")
      .def_readwrite("look_from", &Camera::lookFrom, KeywordDoc("Camera::", "look_from").c_str())
      .def_readwrite("look_at", &Camera::lookAt, KeywordDoc("Camera::", "look_at").c_str())
      .def_readwrite("up", &Camera::up, KeywordDoc("Camera::", "up").c_str())
      .def_readwrite("fov", &Camera::fovDegrees, KeywordDoc("Camera::", "fov").c_str())
      .def_readwrite("orbit", &Camera::orbitDegrees, KeywordDoc("Camera::", "orbit").c_str())
      .def("__repr__", [](const Camera& c) {
        return std::string(py::str("vkpt.Camera(index={}, look_from={}, look_at={}, fov={}, orbit={}{})")
                               .format(py::cast(c.index), py::cast(c.lookFrom), py::cast(c.lookAt),
                                       py::cast(c.fovDegrees), c.orbitDegrees, c.matrix ? ", matrix=..." : ""));
      });
}

}  // namespace vkpt::python

// vkpt.devices() and vkpt.Device: the Vulkan devices a Scene can render on.
#include <string>

#include <pybind11/stl.h>

#include "python/bindings.h"

namespace vkpt::python {

void BindDevices(py::module_& m) {
  py::class_<Device>(m, "Device", R"(A Vulkan device a Scene can render on: Scene(path, device=...) names it by
index or by a substring of its name.)")
      .def_readonly("index", &Device::index, "Scene(path, device=str(index)) names it")
      .def_readonly("name", &Device::name, "as the driver names it")
      .def_readonly("type", &Device::type,
                    "\"discrete GPU\", \"integrated GPU\", \"virtual GPU\", \"CPU\" or \"other\"")
      .def_property_readonly(
          "api_version", [](const Device& d) { return py::make_tuple(d.apiMajor, d.apiMinor); },
          "the Vulkan version it supports, (major, minor)")
      .def_readonly("compute", &Device::compute, "it has a compute queue, which vkpt needs")
      .def("__repr__", [](const Device& d) {
        return "vkpt.Device(index=" + std::to_string(d.index) + ", name=" + std::string(py::repr(py::str(d.name))) +
               ", type=" + std::string(py::repr(py::str(d.type))) + ")";
      });
  m.def("devices", &Devices, R"(The Vulkan devices of this machine (a list of vkpt.Device), in index order;
empty without a Vulkan loader or driver, where backend="auto" renders on the CPU.)");
}

}  // namespace vkpt::python

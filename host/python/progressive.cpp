#include <memory>
#include <utility>

#include <pybind11/stl.h>

#include "python/bindings.h"

namespace vkpt::python {

using namespace pybind11::literals;

PyProgressive BeginOn(PyScene& self, const py::object& camera, RenderOptions options, const py::object& progress) {
  const Camera view = CameraFrom(camera);
  std::shared_ptr<Callbacks> callbacks = Callbacks::Hook(self, progress, options);
  ProgressiveRender render = Serialised(self, [&] { return self.Get().Begin(view, options); });
  return PyProgressive(self, std::move(render), std::move(callbacks));
}

uint32_t PyProgressive::Advance(uint32_t spp) {
  const uint32_t done = Serialised(scene_, [&] {
    scene_.cancelled = false;
    callbacks_->Rearm();
    return render_.Advance(spp);
  });
  callbacks_->RaiseAny();
  return done;
}

PyRender PyProgressive::Result() {
  return PyRender(std::make_shared<RenderResult>(Serialised(scene_, [&] { return render_.Result(); })));
}

void BindProgressive(py::module_& m) {
  py::class_<PyProgressive>(m, "ProgressiveRender", R"(A render taken in steps (Scene.begin), for a window or a preview.

advance(spp) adds samples and returns the samples per pixel so far; result() gives the
render so far as a vkpt.Render, bit-identical after n samples to Scene.render's at
spp=n with the same camera and keywords. It takes samples up to spp (None: 65536); it
ends when its scene begins another, renders, updates or closes, and then raises
vkpt.Error.)")
      .def("advance", &PyProgressive::Advance, "spp"_a = 1,
           "adds up to spp samples per pixel (fewer at the bound or when cancelled); returns the spp so far")
      .def("result", &PyProgressive::Result, "the render so far, with the AOVs and filter the keywords ask for")
      .def_property_readonly(
          "spp", [](PyProgressive& p) { return p.Get().Spp(); }, "samples per pixel so far")
      .def_property_readonly(
          "max_spp", [](PyProgressive& p) { return p.Get().MaxSpp(); }, "the bound on its samples per pixel")
      .def_property_readonly(
          "camera", [](PyProgressive& p) { return p.Get().Camera(); }, "the camera it renders from (a CameraInfo)");
}

}  // namespace vkpt::python

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "python/bindings.h"

namespace vkpt::python {

using namespace pybind11::literals;

PyRender RenderOn(PyScene& self, const py::object& camera, RenderOptions options, const py::object& progress) {
  const Camera view = CameraFrom(camera);
  const std::shared_ptr<Callbacks> callbacks = Callbacks::Hook(self, progress, options);
  auto result = std::make_shared<RenderResult>(Serialised(self, [&] {
    self.cancelled = false;
    return self.Get().Render(view, options);
  }));
  callbacks->RaiseAny();
  return PyRender(std::move(result));
}

py::array PyRender::View(Image& image) const {
  // The capsule holds a reference to the result: the array outlives the Render object.
  auto* owner = new std::shared_ptr<RenderResult>(result_);
  py::capsule base(owner, [](void* p) { delete static_cast<std::shared_ptr<RenderResult>*>(p); });
  return py::array_t<float>({py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(image.channels)},
                            image.data.data(), base);
}

py::array PyRender::ImageArray() const { return View(result_->image); }

py::object PyRender::RawArray() const { return result_->raw ? py::object(View(*result_->raw)) : py::none(); }

py::dict PyRender::AovArrays() const {
  py::dict aovs;
  for (auto& [name, image] : result_->aovs) aovs[py::str(name)] = View(image);
  return aovs;
}

py::dict PyRender::Channels() const {
  py::dict channels;
  channels["image"] = py::cast(result_->image.channelNames);
  if (result_->raw) channels["raw"] = py::cast(result_->raw->channelNames);
  for (const auto& [name, image] : result_->aovs) channels[py::str(name)] = py::cast(image.channelNames);
  return channels;
}

namespace {

std::string Describe(const PyRender& r) {
  const RenderResult& result = r.Result();
  std::string aovs;
  for (const auto& [name, image] : result.aovs) aovs += (aovs.empty() ? ", aovs: " : ", ") + name;
  char text[160];
  std::snprintf(text, sizeof text, "<vkpt.Render %u x %u, %u spp on %s, stopped by %s%s>", result.image.width,
                result.image.height, result.spp, result.engine.c_str(), result.stoppedBy.c_str(), aovs.c_str());
  return text;
}

}  // namespace

void BindRender(py::module_& m) {
  py::class_<PyRender>(m, "Render", R"(One render: its image, AOVs and figures.

image: linear Rec.709 radiance, float32 H x W x 3 (denoised with denoise=True);
raw: the image before the filter (None without denoise, or when cancelled before the
filter ended: then image is unfiltered); aovs: name -> H x W x C array;
ids: with an id AOV, what its ids name (a dict), else None; np.asarray(render) is the
image. The arrays are views of the render's memory.)")
      .def_property_readonly("image", &PyRender::ImageArray,
                             "linear Rec.709 radiance, float32 H x W x 3 (denoised with denoise=True)")
      .def_property_readonly("raw", &PyRender::RawArray,
                             "with denoise=True, the image before the filter; else (or cancelled first) None")
      .def_property_readonly("aovs", &PyRender::AovArrays, "name -> float32 H x W x C array")
      .def_property_readonly(
          "ids",
          [](const PyRender& r) -> py::object {
            const std::string& ids = r.Result().ids;
            if (ids.empty()) return py::none();
            return py::module_::import("json").attr("loads")(ids);
          },
          "with an id AOV, what its ids name (a dict); else None")
      .def_property_readonly("channels", &PyRender::Channels, "channel names of the image, raw and each AOV")
      .def_property_readonly(
          "spp", [](const PyRender& r) { return r.Result().spp; },
          "samples per pixel (adaptive: the most any pixel took)")
      .def_property_readonly(
          "samples", [](const PyRender& r) { return r.Result().samples; }, "every pixel's samples added up")
      .def_property_readonly(
          "stopped_by", [](const PyRender& r) { return r.Result().stoppedBy; },
          "what ended it: \"spp\", \"time\", \"noise_target\", \"converged\" or \"cancelled\"")
      .def_property_readonly(
          "estimated_rel_mse", [](const PyRender& r) { return r.Result().estimatedRelMse; },
          "the image's estimated relative mean squared error")
      .def_property_readonly(
          "seconds", [](const PyRender& r) { return r.Result().seconds; }, "rendering, AOV pass and filter")
      .def_property_readonly(
          "engine", [](const PyRender& r) { return r.Result().engine; }, "the device, or \"cpu\"")
      .def(
          "save",
          [](const PyRender& r, const std::filesystem::path& path, const std::string& view, float exposure) {
            py::gil_scoped_release released;
            return Save(r.Result(), path.string(), view, exposure);
          },
          "path"_a, "view"_a = "neutral", "exposure"_a = 0.0f,
          R"(Writes the render as the vkpt command does, by the extension: .exr (AOVs as layers),
.pfm or .png (AOVs beside it as NAME.<aov>.EXT; PNG through `view`: neutral, agx, aces
or clamp, after `exposure` stops). Returns the paths written.)")
      .def(
          "__array__",
          [](const PyRender& r, const py::object& dtype) {
            py::array image = r.ImageArray();
            return dtype.is_none() ? image : py::array(image.attr("astype")(dtype));
          },
          "dtype"_a = py::none())
      .def("__repr__", &Describe);
}

}  // namespace vkpt::python

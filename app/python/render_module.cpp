// SPDX-License-Identifier: MIT
// The extension module lamina._render: a simulation's (or a world's) current state drawn off
// screen through OSMesa by the renderer of `lamina-headless shot` (app/headless_render.h), to a
// PNG or a numpy array. Its own module because it links OSMesa and the window module links
// libOpenGL: never both in one shared object (docs/rendering.md).
#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "app/headless_render.h"
#include "app/python/bindings.h"
#include "core/render/world_poses.h"
#include "ui/platform/image_file.h"

namespace lamina::python {

namespace {

// the options as core::ParseViewOptions checks them, named as keyword arguments
app::ViewOptions Options(const std::string& size, const std::string& camera,
                         const std::string& overlay, int samples) {
  app::ViewOptions options;
  std::string error;
  if (!core::ParseViewOptions(size, camera, overlay, &options, &error, "")) {
    throw py::value_error(error);
  }
  if (samples != 1 && samples != 2 && samples != 4) {
    throw py::value_error("samples must be 1, 2 or 4, got " + std::to_string(samples));
  }
  options.samples = samples;
  return options;
}

/// One off-screen view: the camera is chosen on the first frame and kept, so a sequence of
/// frames shares it.
class PyRenderer {
 public:
  PyRenderer(const std::string& size, const std::string& camera, const std::string& overlay,
             int samples)
      : options_(Options(size, camera, overlay, samples)) {
    std::string error;
    if (!view_.Open(options_, &error)) throw std::runtime_error("cannot render: " + error);
  }

  // RGBA rows bottom-up, of a Simulator's current state or a WorldModel's initial conditions
  std::vector<std::uint8_t> Draw(py::handle what) {
    if (py::isinstance<PySim>(what)) {
      const PySim& handle = what.cast<const PySim&>();
      if (handle.sim == nullptr)
        throw std::runtime_error("the simulator of a batch run that has ended");
      const core::Simulator& sim = *handle.sim;
      return view_.Render(sim.world(), core::CurrentPoses(sim), &sim);
    }
    if (py::isinstance<PyWorld>(what)) {
      const core::WorldDesc& world = *what.cast<const PyWorld&>().desc;
      return view_.Render(world, core::InitialPoses(world), nullptr);
    }
    throw py::type_error("render: expected a Simulator or a WorldModel");
  }

  void Save(py::handle what, const std::string& path) {
    const std::vector<std::uint8_t> rgba = Draw(what);
    if (!ui::WritePngBottomUp(path, options_.width, options_.height, rgba)) {
      throw std::runtime_error(path + ": cannot write the image");
    }
  }

  // height x width x 3 uint8, top row first
  py::array_t<std::uint8_t> Pixels(py::handle what) {
    const std::vector<std::uint8_t> rgba = Draw(what);
    const int w = options_.width, h = options_.height;
    py::array_t<std::uint8_t> out({h, w, 3});
    std::uint8_t* dst = out.mutable_data();
    for (int row = 0; row < h; ++row) {
      const std::uint8_t* src = rgba.data() + static_cast<size_t>(h - 1 - row) * w * 4;
      for (int x = 0; x < w; ++x, dst += 3) std::memcpy(dst, src + 4 * x, 3);
    }
    return out;
  }

  std::string Camera() const { return core::FormatCamera(view_.camera()); }

 private:
  app::ViewOptions options_;
  app::OffscreenView view_;
};

}  // namespace

}  // namespace lamina::python

PYBIND11_MODULE(_render, m) {
  using lamina::python::PyRenderer;
  namespace py = pybind11;
  m.doc() = "Off-screen rendering (OSMesa) of Lamina simulations";
  py::module_::import("lamina._lamina");  // Simulator and WorldModel
  py::class_<PyRenderer>(m, "OffscreenRenderer")
      .def(py::init<const std::string&, const std::string&, const std::string&, int>(),
           py::arg("size") = "1280x720", py::arg("camera") = "", py::arg("overlay") = "",
           py::arg("samples") = 4,
           "size 'WxH'; camera and overlay as lamina-headless shot's --camera and --overlay.")
      .def("save", &PyRenderer::Save, py::arg("sim"), py::arg("fn"),
           "Draws a Simulator's current state (or a WorldModel's initial one) to a PNG.")
      .def("pixels", &PyRenderer::Pixels, py::arg("sim"),
           "The same picture as a height x width x 3 uint8 numpy array, top row first.")
      .def("camera", &PyRenderer::Camera,
           "The camera as lamina-headless --camera text (chosen on the first picture).");
}

// SPDX-License-Identifier: MIT
// The extension module lamina._window: Lamina's window on a simulation Python drives
// (ui/viewer/script_window.h), for lamina.vis.run. Its own module because it links GLFW and
// libOpenGL, and lamina._render links OSMesa.
#include <stdexcept>
#include <string>

#include <pybind11/pybind11.h>

#include "app/python/bindings.h"
#include "core/render/view_options.h"
#include "ui/viewer/script_window.h"

namespace lamina::python {

namespace {

// runs the window with the GIL released; the hooks take it back to call Python
void Run(py::object sim, py::object idle, const std::string& size, const std::string& camera,
         const std::string& overlay, bool running, int frames, const std::string& screenshot) {
  if (!py::isinstance<PySim>(sim)) throw py::type_error("run: expected a Simulator");
  const PySim& handle = sim.cast<const PySim&>();
  handle.get();  // a batch run's simulator after its run raises here
  core::ViewOptions view;
  std::string error;
  if (!core::ParseViewOptions(size, camera, overlay, &view, &error, "")) {
    throw py::value_error(error);
  }
  if (frames < 0) throw py::value_error("frames must be >= 0, got " + std::to_string(frames));
  ui::ScriptWindowOptions options;
  options.width = view.width;
  options.height = view.height;
  options.camera = view.camera;
  options.overlays = view.overlays;
  options.running = running;
  options.frames = frames;
  options.screenshot = screenshot;
  ui::ScriptWindowHooks hooks;
  hooks.simulator = [&handle]() -> const core::Simulator& { return handle.get(); };
  hooks.advance = [&](double seconds) {
    py::gil_scoped_acquire gil;
    if (idle.is_none()) {
      sim.attr("simulate")(seconds);  // real time: the frame's wall-clock seconds
      return true;
    }
    const py::object result = idle();
    return !(py::isinstance<py::bool_>(result) && !result.cast<bool>());
  };
  bool ok = false;
  {
    py::gil_scoped_release release;
    ok = ui::RunScriptWindow(options, hooks, &error);
  }
  if (!ok) throw std::runtime_error("lamina.vis.run: " + error);
}

}  // namespace

}  // namespace lamina::python

PYBIND11_MODULE(_window, m) {
  namespace py = pybind11;
  m.doc() = "Lamina's window on a simulation Python drives";
  py::module_::import("lamina._lamina");  // Simulator
  m.def("run", &lamina::python::Run, py::arg("sim"), py::arg("idle") = py::none(),
        py::arg("size") = "1280x720", py::arg("camera") = "", py::arg("overlay") = "",
        py::arg("running") = false, py::arg("frames") = 0, py::arg("screenshot") = "");
}

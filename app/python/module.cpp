// SPDX-License-Identifier: MIT
// The extension module lamina._lamina; the package lamina (app/python/lamina) re-exports it
// under Klamp't's names.
#include <pybind11/pybind11.h>

#include "app/python/bindings.h"

PYBIND11_MODULE(_lamina, m) {
  m.doc() = "Lamina: Klamp't's simulation API on Lamina's core";
  lamina::python::BindWorld(m);
  lamina::python::BindSim(m);
  lamina::python::BindController(m);
  lamina::python::BindSensor(m);
  lamina::python::BindBatch(m);
  lamina::python::BindTrajectory(m);
}

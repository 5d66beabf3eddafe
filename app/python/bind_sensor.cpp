// SPDX-License-Identifier: MIT
// SimRobotSensor: Klamp't's sensor object (robotsim.SimRobotSensor) on one of a simulated
// robot's core::Sensor (docs/sensors.md). Settings changed here apply from the sensor's next
// sample and are not saved with the world (the robot's `sensors` property keeps the file's text).
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "app/python/bindings.h"
#include "core/sensors/robot_sensors.h"

namespace lamina::python {

namespace {

core::Sensor& S(const PySensor& s) {
  return s.sim->get().sensors(s.robot).sensor(s.index);
}

std::string Setting(const PySensor& s, const std::string& key) {
  std::string text;
  if (!S(s).GetSetting(key, &text)) {
    throw py::key_error("a " + std::string(S(s).type()) + " has no setting '" + key + "'");
  }
  return text;
}

void SetSetting(const PySensor& s, const std::string& key, py::handle value) {
  const std::string text = py::isinstance<py::str>(value) ? value.cast<std::string>()
                                                          : py::str(value).cast<std::string>();
  std::string error;
  if (!S(s).SetSetting(key, text, &error)) throw py::value_error(error);
}

}  // namespace

void BindSensor(py::module_& m) {
  py::class_<PySensor>(m, "SimRobotSensor")
      .def("name", [](const PySensor& s) { return S(s).name(); })
      .def("type", [](const PySensor& s) { return std::string(S(s).type()); })
      .def("measurementNames", [](const PySensor& s) { return S(s).MeasurementNames(); })
      .def("getMeasurements", [](const PySensor& s) { return S(s).measurements(); })
      .def("settings",
           [](const PySensor& s) {
             std::vector<std::string> keys;
             for (const auto& [key, text] : S(s).Settings()) keys.push_back(key);
             return keys;
           })
      .def("getSetting", &Setting)
      .def("setSetting", &SetSetting)
      .def("getEnabled", [](const PySensor& s) { return S(s).enabled(); })
      .def("setEnabled",
           [](const PySensor& s, bool on) { SetSetting(s, "enabled", py::str(on ? "1" : "0")); })
      .def("getLink", [](const PySensor& s) { return S(s).link(); })
      .def("__repr__", [](const PySensor& s) {
        return "<SimRobotSensor '" + S(s).name() + "' (" + S(s).type() + ")>";
      });
}

}  // namespace lamina::python

// SPDX-License-Identifier: MIT
// SimRobotController: Klamp't's controller commands on core::RobotController. A refused
// command raises ValueError with the controller's message and changes nothing.
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "app/python/bindings.h"
#include "core/control/robot_controller.h"
#include "core/sensors/robot_sensors.h"

namespace lamina::python {

namespace {

using core::RobotController;
using core::VecX;

RobotController& C(const PyController& c) {
  return c.sim->get().controller(c.robot);
}

// a sensor by index (negative from the end, as Python) or name
int SensorIndex(const core::RobotSensors& sensors, py::handle which) {
  if (py::isinstance<py::str>(which)) {
    const std::string name = which.cast<std::string>();
    const int i = sensors.Find(name);
    if (i < 0) throw py::key_error("no sensor named '" + name + "'");
    return i;
  }
  int i = which.cast<int>();
  if (i < 0) i += sensors.size();
  if (i < 0 || i >= sensors.size()) {
    throw py::index_error("sensor " + std::to_string(which.cast<int>()) + ": the robot has " +
                          std::to_string(sensors.size()) + " sensors");
  }
  return i;
}

void Check(const RobotController& controller, bool ok) {
  if (!ok) throw py::value_error(controller.last_error());
}

}  // namespace

void BindController(py::module_& m) {
  py::class_<PyController>(m, "SimRobotController")
      .def("getCommandedConfig",
           [](const PyController& c) {
             VecX q;
             if (!C(c).GetCommandedConfig(&q)) {
               throw std::runtime_error("getCommandedConfig: some driver is not in PID mode");
             }
             return ToList(q);
           })
      .def("getCommandedVelocity",
           [](const PyController& c) {
             VecX dq;
             if (!C(c).GetCommandedVelocity(&dq)) {
               throw std::runtime_error("getCommandedVelocity: some driver is not in PID mode");
             }
             return ToList(dq);
           })
      .def("getCommandedTorque",
           [](const PyController& c) { return ToList(C(c).CommandedTorques()); })
      .def("getSensedConfig", [](const PyController& c) { return ToList(C(c).sensed_config()); })
      .def("getSensedVelocity",
           [](const PyController& c) { return ToList(C(c).sensed_velocity()); })
      .def(
          "setMilestone",
          [](const PyController& c, py::handle q, py::handle dq) {
            RobotController& k = C(c);
            Check(k,
                  dq.is_none() ? k.SetMilestone(ToVecX(q)) : k.SetMilestone(ToVecX(q), ToVecX(dq)));
          },
          py::arg("q"), py::arg("dq") = py::none())
      .def(
          "addMilestone",
          [](const PyController& c, py::handle q, py::handle dq) {
            RobotController& k = C(c);
            Check(k,
                  dq.is_none() ? k.AddMilestone(ToVecX(q)) : k.AddMilestone(ToVecX(q), ToVecX(dq)));
          },
          py::arg("q"), py::arg("dq") = py::none())
      .def("addMilestoneLinear",
           [](const PyController& c, py::handle q) {
             RobotController& k = C(c);
             Check(k, k.AddMilestoneLinear(ToVecX(q)));
           })
      .def("setLinear",
           [](const PyController& c, py::handle q, double dt) {
             RobotController& k = C(c);
             Check(k, k.SetLinear(ToVecX(q), dt));
           })
      .def("addLinear",
           [](const PyController& c, py::handle q, double dt) {
             RobotController& k = C(c);
             Check(k, k.AddLinear(ToVecX(q), dt));
           })
      .def("setCubic",
           [](const PyController& c, py::handle q, py::handle v, double dt) {
             RobotController& k = C(c);
             Check(k, k.SetCubic(ToVecX(q), ToVecX(v), dt));
           })
      .def("addCubic",
           [](const PyController& c, py::handle q, py::handle v, double dt) {
             RobotController& k = C(c);
             Check(k, k.AddCubic(ToVecX(q), ToVecX(v), dt));
           })
      .def("setVelocity",
           [](const PyController& c, py::handle dq, double dt) {
             RobotController& k = C(c);
             Check(k, k.SetVelocity(ToVecX(dq), dt));
           })
      .def(
          "setPIDCommand",
          [](const PyController& c, py::handle q, py::handle dq, py::handle torque) {
            RobotController& k = C(c);
            Check(k, torque.is_none() ? k.SetPIDCommand(ToVecX(q), ToVecX(dq))
                                      : k.SetPIDCommand(ToVecX(q), ToVecX(dq), ToVecX(torque)));
          },
          py::arg("qdes"), py::arg("dqdes"), py::arg("tfeedforward") = py::none())
      .def("setPIDGains",
           [](const PyController& c, py::handle kp, py::handle ki, py::handle kd) {
             RobotController& k = C(c);
             Check(k, k.SetPIDGains(ToVecX(kp), ToVecX(ki), ToVecX(kd)));
           })
      .def("getPIDGains",
           [](const PyController& c) {
             VecX kp, ki, kd;
             C(c).GetPIDGains(&kp, &ki, &kd);
             return py::make_tuple(ToList(kp), ToList(ki), ToList(kd));
           })
      .def("setTorque",
           [](const PyController& c, py::handle t) {
             RobotController& k = C(c);
             Check(k, k.SetTorque(ToVecX(t)));
           })
      .def("setManualMode", [](const PyController& c, bool on) { C(c).SetManualMode(on); })
      .def("setRate",
           [](const PyController& c, double dt) {
             RobotController& k = C(c);
             if (!k.SetControlPeriod(dt)) throw py::value_error("setRate: the period must be > 0");
           })
      .def("getRate", [](const PyController& c) { return C(c).control_period(); })
      .def("remainingTime", [](const PyController& c) { return C(c).RemainingTime(); })
      // sensors (bind_sensor.cpp): by index or name; IndexError / KeyError when missing
      .def("numSensors", [](const PyController& c) { return c.sim->get().sensors(c.robot).size(); })
      .def("sensor", [](const PyController& c, py::handle which) {
        const core::RobotSensors& sensors = c.sim->get().sensors(c.robot);
        return PySensor{c.sim, c.robot, SensorIndex(sensors, which)};
      });
}

}  // namespace lamina::python

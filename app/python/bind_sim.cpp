// SPDX-License-Identifier: MIT
// Simulator and SimBody: Klamp't's simulation API on core::Simulator (core/sim/simulator.h).
// Bodies are named by world id or by a model (anything with getID()); vectors are lists, and
// numpy arrays are accepted wherever lists are.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "app/python/bindings.h"
#include "core/model/surface_rows.h"
#include "core/sim/sim_access.h"
#include "core/sim/sim_state.h"
#include "core/sim/step_observer.h"

namespace lamina::python {

namespace {

using core::Simulator;

int OptionalId(py::handle element) {
  return element.is_none() ? -1 : ElementId(element);
}

py::list ContactRows(const Simulator& s, int a, int b) {
  py::list rows;
  for (const core::FeedbackContact& c : s.GetContacts(a, b)) {
    py::list row(7);
    for (int k = 0; k < 3; ++k) {
      row[static_cast<size_t>(k)] = c.position[k];
      row[static_cast<size_t>(3 + k)] = c.normal[k];
    }
    row[6] = c.friction;
    rows.append(row);
  }
  return rows;
}

py::list Vec3Rows(const std::vector<core::Vec3>& vectors) {
  py::list rows;
  for (const core::Vec3& v : vectors) rows.append(ToList(v));
  return rows;
}

Simulator& S(const PyBody& b) {
  return b.sim->get();
}

core::SimBody Body(const PyBody& b) {
  return S(b).body(b.id);
}

// SurfaceParameters: one property per surface row of the parameter table (its key, its help),
// and a value the table refuses raises ValueError with the table's message
void BindSurfaceParameters(py::module_& m) {
  py::class_<core::SurfaceDesc> surface(m, "SurfaceParameters");
  surface.def(py::init<>());
  for (const core::SurfaceRow& row : core::SurfaceMembers()) {
    const core::ParamSpec* spec = row.spec;
    double core::SurfaceDesc::*member = row.member;
    surface.def_property(
        std::string(spec->key).c_str(), [member](const core::SurfaceDesc& s) { return s.*member; },
        [spec, member](core::SurfaceDesc& s, double value) {
          if (auto why = core::CheckParam(*spec, core::ParamValue{value}, 1)) {
            throw py::value_error(std::string(spec->key) + ": " + *why);
          }
          s.*member = value;
        },
        std::string(spec->help).c_str());
  }
}

}  // namespace

void BindSim(py::module_& m) {
  BindSurfaceParameters(m);

  py::class_<core::SimState>(m, "SimState", "An exact snapshot of a simulation (getState)");

  py::class_<PySim, std::shared_ptr<PySim>>(m, "Simulator")
      .def(py::init([](const PyWorld& world) {
             auto sim = std::make_shared<PySim>();
             sim->desc = world.desc;
             sim->owned = std::make_unique<Simulator>(*world.desc);
             sim->sim = sim->owned.get();
             return sim;
           }),
           py::arg("world"))
      .def(
          "simulate",
          [](PySim& s, double dt) {
            Simulator& sim = s.get();
            py::gil_scoped_release release;
            s.status = sim.Simulate(dt);
          },
          py::arg("t"), "Advances by t seconds (the GIL is released meanwhile).")
      .def(
          "_simulateLoop",
          [](PySim& s, double dt, int calls) {
            Simulator& sim = s.get();
            py::gil_scoped_release release;
            for (int i = 0; i < calls; ++i) s.status = sim.Simulate(dt);
          },
          py::arg("t"), py::arg("calls"),
          "simulate(t) `calls` times in a C++ loop: the baseline of the Python-overhead "
          "benchmark (tests/bench/python_overhead.py).")
      .def(
          "fakeSimulate", [](PySim& s, double dt) { s.get().FakeSimulate(dt); }, py::arg("t"))
      .def("getTime", [](const PySim& s) { return s.get().time(); })
      .def("reset",
           [](PySim& s) {
             s.get().Reset();
             s.status = core::StepStatus::kNormal;
           })
      .def("getState", [](const PySim& s) { return s.get().GetState(); })
      .def("setState", [](PySim& s, const core::SimState& state) { s.get().SetState(state); })
      .def("setGravity",
           [](PySim& s, py::handle g) { s.get().SetGravity(ToVec3(g, "setGravity")); })
      .def("getGravity", [](const PySim& s) { return ToList(s.get().world().settings.gravity); })
      .def("setSimStep", [](PySim& s, double dt) { s.get().SetSimStep(dt); })
      .def("getSimStep", [](const PySim& s) { return s.get().sim_step(); })
      .def("setSetting",
           [](PySim& s, const std::string& name, const std::string& value) {
             // Klamp't's text separates numbers by blanks, access paths' by commas
             std::string text;
             for (py::handle word : py::str(value).attr("split")()) {
               text += (text.empty() ? "" : ",") + word.cast<std::string>();
             }
             std::string error;
             if (!core::SetPathText(&s.get(), "settings." + name, text, &error)) {
               throw py::value_error(error);
             }
           })
      .def("getSetting",
           [](const PySim& s, const std::string& name) {
             std::string error;
             const auto target = core::ResolveSimulationPath(s.get(), "settings." + name, &error);
             const auto value = target ? core::GetPath(s.get(), *target, &error) : std::nullopt;
             if (!value) throw py::value_error(error);
             return core::FormatAccessValue(*target, *value);
           })
      .def("updateWorld", [](const PySim& s) { s.get().UpdateWorld(s.desc.get()); })
      .def("getWorld", [](const PySim& s) { return PyWorld{s.desc}; })
      .def("getStatus", [](const PySim& s) { return core::KlamptStatusCode(s.status); })
      .def(
          "getStatusString",
          [](const PySim& s, int status) {
            // Klamp't's numbers; without one, the last call's status by Lamina's own name
            if (status < 0) return std::string(core::StepStatusName(s.status));
            if (status > core::KlamptStatusCode(core::StepStatus::kError)) {
              throw py::value_error("no status " + std::to_string(status));
            }
            return std::string(core::StepStatusName(core::StatusOfKlamptCode(status)));
          },
          py::arg("s") = -1)
      .def("getActualConfig",
           [](const PySim& s, py::handle robot) {
             return ToList(s.get().GetRobotConfig(RobotIndex(s.get().world(), robot)));
           })
      .def("getActualVelocity",
           [](const PySim& s, py::handle robot) {
             return ToList(s.get().GetRobotVelocity(RobotIndex(s.get().world(), robot)));
           })
      .def("getActualTorques",
           [](const PySim& s, py::handle robot) {
             return ToList(s.get().GetActuatorTorques(RobotIndex(s.get().world(), robot)));
           })
      .def("getActualTorque",
           [](const PySim& s, py::handle robot) {
             return ToList(s.get().GetActuatorTorques(RobotIndex(s.get().world(), robot)));
           })
      .def("body",
           [](const std::shared_ptr<PySim>& s, py::handle element) {
             const int id = ElementId(element);
             if (!s->get().body(id).valid()) {
               throw py::index_error("no terrain, object or link has id " + std::to_string(id));
             }
             return PyBody{s, id};
           })
      .def("controller",
           [](const std::shared_ptr<PySim>& s, py::handle robot) {
             return PyController{s, RobotIndex(s->get().world(), robot)};
           })
      // contact feedback: normals point into a, forces act on a (one convention)
      .def("enableContactFeedbackAll", [](PySim& s) { s.get().EnableContactFeedbackAll(); })
      .def("enableContactFeedback",
           [](PySim& s, py::handle a, py::handle b) {
             s.get().EnableContactFeedback(ElementId(a), ElementId(b));
           })
      .def(
          "inContact",
          [](const PySim& s, py::handle a, py::handle b) {
            return s.get().InContact(ElementId(a), OptionalId(b));
          },
          py::arg("aid"), py::arg("bid") = py::none())
      .def(
          "hadContact",
          [](const PySim& s, py::handle a, py::handle b) {
            return s.get().HadContact(ElementId(a), OptionalId(b));
          },
          py::arg("aid"), py::arg("bid") = py::none())
      .def(
          "hadSeparation",
          [](const PySim& s, py::handle a, py::handle b) {
            return s.get().HadSeparation(ElementId(a), OptionalId(b));
          },
          py::arg("aid"), py::arg("bid") = py::none())
      .def(
          "hadPenetration",
          [](const PySim& s, py::handle a, py::handle b) {
            return s.get().HadPenetration(ElementId(a), OptionalId(b));
          },
          py::arg("aid"), py::arg("bid") = py::none())
      .def("getContacts",
           [](const PySim& s, py::handle a, py::handle b) {
             return ContactRows(s.get(), ElementId(a), ElementId(b));
           })
      .def("getContactForces",
           [](const PySim& s, py::handle a, py::handle b) {
             return Vec3Rows(s.get().GetContactForces(ElementId(a), ElementId(b)));
           })
      .def(
          "contactForce",
          [](const PySim& s, py::handle a, py::handle b) {
            return ToList(s.get().ContactForce(ElementId(a), OptionalId(b)));
          },
          py::arg("aid"), py::arg("bid") = py::none())
      .def(
          "contactTorque",
          [](const PySim& s, py::handle a, py::handle b) {
            return ToList(s.get().ContactTorque(ElementId(a), OptionalId(b)));
          },
          py::arg("aid"), py::arg("bid") = py::none())
      .def(
          "meanContactForce",
          [](const PySim& s, py::handle a, py::handle b) {
            return ToList(s.get().MeanContactForce(ElementId(a), OptionalId(b)));
          },
          py::arg("aid"), py::arg("bid") = py::none())
      .def(
          "meanContactTorque",
          [](const PySim& s, py::handle a, py::handle b) {
            return ToList(s.get().MeanContactTorque(ElementId(a), OptionalId(b)));
          },
          py::arg("aid"), py::arg("bid") = py::none());

  py::class_<PyBody>(m, "SimBody")
      .def("getID", [](const PyBody& b) { return b.id; })
      .def(
          "enable", [](const PyBody& b, bool on) { Body(b).Enable(on); }, py::arg("enabled") = true)
      .def("isEnabled", [](const PyBody& b) { return Body(b).enabled(); })
      .def(
          "enableDynamics", [](const PyBody& b, bool on) { Body(b).EnableDynamics(on); },
          py::arg("enabled") = true)
      .def("isDynamicsEnabled", [](const PyBody& b) { return Body(b).dynamics_enabled(); })
      .def("getTransform", [](const PyBody& b) { return PoseToPy(Body(b).GetTransform()); })
      .def("setTransform",
           [](const PyBody& b, py::handle R, py::handle t) {
             Body(b).SetTransform(PoseFromPy(py::make_tuple(R, t)));
           })
      .def("getObjectTransform", [](const PyBody& b) { return PoseToPy(Body(b).GetTransform()); })
      .def("setObjectTransform",
           [](const PyBody& b, py::handle R, py::handle t) {
             Body(b).SetTransform(PoseFromPy(py::make_tuple(R, t)));
           })
      .def("getVelocity",
           [](const PyBody& b) {
             const core::Twist v = Body(b).GetVelocity();
             return py::make_tuple(ToList(v.angular), ToList(v.linear));
           })
      .def("setVelocity",
           [](const PyBody& b, py::handle w, py::handle v) {
             Body(b).SetVelocity(core::Twist{ToVec3(v, "v"), ToVec3(w, "w")});
           })
      .def("getSurface", [](const PyBody& b) { return Body(b).GetSurface(); })
      .def("setSurface",
           [](const PyBody& b, const core::SurfaceDesc& surface) { Body(b).SetSurface(surface); })
      .def("getCollisionPadding", [](const PyBody& b) { return Body(b).GetPadding(); })
      .def("setCollisionPadding", [](const PyBody& b, double p) { Body(b).SetPadding(p); })
      .def("applyForceAtPoint",
           [](const PyBody& b, py::handle f, py::handle p) {
             Body(b).ApplyForceAtPoint(ToVec3(f, "force"), ToVec3(p, "point"));
           })
      .def("applyForceAtLocalPoint",
           [](const PyBody& b, py::handle f, py::handle p) {
             Body(b).ApplyForceAtLocalPoint(ToVec3(f, "force"), ToVec3(p, "point"));
           })
      .def("applyForceAtObjectLocalPoint",
           [](const PyBody& b, py::handle f, py::handle p) {
             Body(b).ApplyForceAtLocalPoint(ToVec3(f, "force"), ToVec3(p, "point"));
           })
      .def("applyWrench", [](const PyBody& b, py::handle f, py::handle t) {
        Body(b).ApplyWrench(ToVec3(f, "force"), ToVec3(t, "torque"));
      });
}

}  // namespace lamina::python

// SPDX-License-Identifier: MIT
// WorldModel, RobotModel, RobotModelLink, RigidObjectModel, TerrainModel: Klamp't's model
// classes on a WorldDesc. A robot's configuration and velocity and an object's transform and
// velocity are the description's initial conditions (what a Simulator starts from).
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "app/python/bindings.h"
#include "core/control/config_space.h"
#include "core/diagnostics.h"
#include "core/io/load_context.h"
#include "core/io/world_file.h"
#include "core/robot/kinematics.h"

namespace lamina::python {

namespace {

using core::WorldDesc;

// index of element `which` (an int or a name) among `count` elements named by `name_of`
template <typename NameOf>
int ElementIndex(py::handle which, int count, const char* kind, NameOf name_of) {
  int index = -1;
  if (py::isinstance<py::str>(which)) {
    const std::string name = which.cast<std::string>();
    for (int i = 0; i < count && index < 0; ++i) {
      if (name_of(i) == name) index = i;
    }
    if (index < 0) throw py::key_error(std::string("no ") + kind + " is named '" + name + "'");
    return index;
  }
  index = which.cast<int>();
  if (index < 0 || index >= count) {
    throw py::index_error(std::string(kind) + " " + std::to_string(index) + ": there are " +
                          std::to_string(count));
  }
  return index;
}

core::RobotDesc& Robot(const PyElement& r) {
  if (r.index < 0 || r.index >= static_cast<int>(r.desc->robots.size())) {
    throw py::index_error("the robot is no longer in its world");
  }
  return r.desc->robots[static_cast<size_t>(r.index)];
}

core::RigidObjectDesc& Object(const PyElement& o) {
  if (o.index < 0 || o.index >= static_cast<int>(o.desc->objects.size())) {
    throw py::index_error("the rigid object is no longer in its world");
  }
  return o.desc->objects[static_cast<size_t>(o.index)];
}

core::TerrainDesc& Terrain(const PyElement& t) {
  if (t.index < 0 || t.index >= static_cast<int>(t.desc->terrains.size())) {
    throw py::index_error("the terrain is no longer in its world");
  }
  return t.desc->terrains[static_cast<size_t>(t.index)];
}

core::VecX RobotVector(const core::RobotDesc& robot, py::handle value, const char* what) {
  core::VecX v = ToVecX(value);
  if (v.size() != robot.dof()) {
    throw py::value_error(std::string(what) + " needs " + std::to_string(robot.dof()) +
                          " numbers (one per link), got " + std::to_string(v.size()));
  }
  if (!v.allFinite()) throw py::value_error(std::string(what) + " must be finite");
  return v;
}

PyLink Link(const PyRobot& r, py::handle which) {
  const core::RobotDesc& robot = Robot(r);
  const int l = ElementIndex(which, robot.dof(), "link",
                             [&](int i) { return robot.links[static_cast<size_t>(i)].name; });
  return PyLink{r.desc, r.index, l};
}

void ReadFile(PyWorld& w, const std::string& path) {
  if (!w.desc->robots.empty() || !w.desc->objects.empty() || !w.desc->terrains.empty()) {
    throw std::runtime_error("readFile: the world is not empty (load into a new WorldModel)");
  }
  core::Diagnostics diagnostics;
  core::MeshCache meshes;
  core::LoadContext context{diagnostics, meshes};
  WorldDesc loaded;
  const bool ok = core::LoadWorldFile(path, context, &loaded);
  if (!ok || diagnostics.HasErrors()) {
    std::string message;
    for (const std::string& line : diagnostics.Messages(core::Severity::kError)) {
      message += (message.empty() ? "" : "\n") + line;
    }
    throw std::runtime_error(message.empty() ? path + ": could not be loaded" : message);
  }
  *w.desc = std::move(loaded);
}

}  // namespace

void BindWorld(py::module_& m) {
  py::class_<PyWorld>(m, "WorldModel")
      .def(py::init<>())
      .def(py::init([](const std::string& path) {
             PyWorld w;
             ReadFile(w, path);
             return w;
           }),
           py::arg("fn"))
      .def("readFile", &ReadFile, py::arg("fn"),
           "Loads a world (.xml) or a single robot, object or terrain file into this empty "
           "world; raises RuntimeError with every file:line: error message on failure.")
      .def("loadFile", &ReadFile, py::arg("fn"))
      .def("numRobots", [](const PyWorld& w) { return w.desc->robots.size(); })
      .def("numRigidObjects", [](const PyWorld& w) { return w.desc->objects.size(); })
      .def("numTerrains", [](const PyWorld& w) { return w.desc->terrains.size(); })
      .def("numIDs", [](const PyWorld& w) { return w.desc->IdCount(); })
      .def("robot",
           [](const PyWorld& w, py::handle which) {
             const auto& robots = w.desc->robots;
             return PyRobot{{w.desc, ElementIndex(which, static_cast<int>(robots.size()), "robot",
                                                  [&](int i) { return robots[i].name; })}};
           })
      .def("rigidObject",
           [](const PyWorld& w, py::handle which) {
             const auto& objects = w.desc->objects;
             return PyRigidObject{
                 {w.desc, ElementIndex(which, static_cast<int>(objects.size()), "rigid object",
                                       [&](int i) { return objects[i].name; })}};
           })
      .def("terrain",
           [](const PyWorld& w, py::handle which) {
             const auto& terrains = w.desc->terrains;
             return PyTerrain{
                 {w.desc, ElementIndex(which, static_cast<int>(terrains.size()), "terrain",
                                       [&](int i) { return terrains[i].name; })}};
           })
      .def("robotLink",
           [](const PyWorld& w, py::handle robot, py::handle link) {
             return Link(PyRobot{{w.desc, RobotIndex(*w.desc, robot)}}, link);
           })
      .def("robotlink",
           [](const PyWorld& w, py::handle robot, py::handle link) {
             return Link(PyRobot{{w.desc, RobotIndex(*w.desc, robot)}}, link);
           })
      .def("getName", [](const PyWorld& w, int id) -> std::string {
        const core::WorldId which = w.desc->Resolve(id);
        switch (which.kind) {
          case core::WorldId::Kind::kTerrain:
            return w.desc->terrains[static_cast<size_t>(which.index)].name;
          case core::WorldId::Kind::kRigidObject:
            return w.desc->objects[static_cast<size_t>(which.index)].name;
          case core::WorldId::Kind::kRobot:
            return w.desc->robots[static_cast<size_t>(which.index)].name;
          case core::WorldId::Kind::kRobotLink:
            return w.desc->robots[static_cast<size_t>(which.index)]
                .links[static_cast<size_t>(which.link)]
                .name;
          case core::WorldId::Kind::kInvalid:
            break;
        }
        throw py::index_error("no element has id " + std::to_string(id));
      });

  py::class_<PyRobot>(m, "RobotModel")
      .def("getID", [](const PyRobot& r) { return r.desc->RobotId(r.index); })
      .def("getName", [](const PyRobot& r) { return Robot(r).name; })
      .def("getIndex", [](const PyRobot& r) { return r.index; })
      .def("numLinks", [](const PyRobot& r) { return Robot(r).dof(); })
      .def("numDrivers", [](const PyRobot& r) { return Robot(r).drivers.size(); })
      .def("link", &Link)
      .def("getConfig", [](const PyRobot& r) { return ToList(Robot(r).InitialConfig()); })
      .def("setConfig",
           [](const PyRobot& r, py::handle q) {
             core::RobotDesc& robot = Robot(r);
             robot.config = RobotVector(robot, q, "setConfig");
           })
      .def("getVelocity", [](const PyRobot& r) { return ToList(Robot(r).InitialVelocity()); })
      .def("setVelocity",
           [](const PyRobot& r, py::handle dq) {
             core::RobotDesc& robot = Robot(r);
             robot.velocity = RobotVector(robot, dq, "setVelocity");
           })
      .def(
          "interpolate",
          [](const PyRobot& r, py::handle a, py::handle b, double u) {
            const core::RobotDesc& robot = Robot(r);
            return ToList(core::InterpolateConfig(robot, RobotVector(robot, a, "interpolate a"),
                                                  RobotVector(robot, b, "interpolate b"), u));
          },
          py::arg("a"), py::arg("b"), py::arg("u"),
          "The configuration a fraction u of the way from a to b (spin joints the short way).")
      .def(
          "interpolateDeriv",
          [](const PyRobot& r, py::handle a, py::handle b) {
            const core::RobotDesc& robot = Robot(r);
            return ToList(core::ConfigDifference(robot, RobotVector(robot, a, "interpolateDeriv a"),
                                                 RobotVector(robot, b, "interpolateDeriv b")));
          },
          py::arg("a"), py::arg("b"), "d/du of interpolate(a, b, u): b - a (spin joints wrapped).");

  py::class_<PyLink>(m, "RobotModelLink")
      .def("getID", [](const PyLink& l) { return l.desc->RobotLinkId(l.robot, l.link); })
      .def("getName",
           [](const PyLink& l) {
             return Robot(PyElement{l.desc, l.robot}).links[static_cast<size_t>(l.link)].name;
           })
      .def("getIndex", [](const PyLink& l) { return l.link; })
      .def("getParent",
           [](const PyLink& l) {
             return Robot(PyElement{l.desc, l.robot}).links[static_cast<size_t>(l.link)].parent;
           })
      .def("robot",
           [](const PyLink& l) {
             return PyRobot{{l.desc, l.robot}};
           })
      .def("getTransform", [](const PyLink& l) {
        const core::RobotDesc& robot = Robot(PyElement{l.desc, l.robot});
        return PoseToPy(
            core::LinkTransforms(robot, robot.InitialConfig())[static_cast<size_t>(l.link)]);
      });

  py::class_<PyRigidObject>(m, "RigidObjectModel")
      .def("getID", [](const PyRigidObject& o) { return o.desc->ObjectId(o.index); })
      .def("getName", [](const PyRigidObject& o) { return Object(o).name; })
      .def("getIndex", [](const PyRigidObject& o) { return o.index; })
      .def("getMass", [](const PyRigidObject& o) { return Object(o).mass; })
      .def("getCom", [](const PyRigidObject& o) { return ToList(Object(o).com); })
      .def("getInertia",
           [](const PyRigidObject& o) {
             const core::Mat3& inertia = Object(o).inertia;  // symmetric: row = column major
             return ToList(std::vector<double>(inertia.data(), inertia.data() + 9));
           })
      .def("getTransform", [](const PyRigidObject& o) { return PoseToPy(Object(o).pose); })
      .def("setTransform", [](const PyRigidObject& o, py::handle R,
                              py::handle t) { Object(o).pose = PoseFromPy(py::make_tuple(R, t)); })
      .def("getVelocity",
           [](const PyRigidObject& o) {
             const core::Twist& v = Object(o).initial_velocity;
             return py::make_tuple(ToList(v.angular), ToList(v.linear));
           })
      .def("setVelocity", [](const PyRigidObject& o, py::handle w, py::handle v) {
        Object(o).initial_velocity = core::Twist{ToVec3(v, "v"), ToVec3(w, "w")};
      });

  py::class_<PyTerrain>(m, "TerrainModel")
      .def("getID", [](const PyTerrain& t) { return t.desc->TerrainId(t.index); })
      .def("getName", [](const PyTerrain& t) { return Terrain(t).name; })
      .def("getIndex", [](const PyTerrain& t) { return t.index; });
}

}  // namespace lamina::python

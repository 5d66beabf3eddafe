// SPDX-License-Identifier: MIT
// The Python module `lamina` (Klamp't's Python API on Lamina's core): the handles the bound
// classes wrap, the conversions between Python values and the core's types, and one Bind
// function per translation unit. Thin: every rule lives in core/.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "core/math_types.h"
#include "core/model/access_path.h"
#include "core/model/world_desc.h"
#include "core/sim/simulator.h"

namespace lamina::python {

namespace py = pybind11;

/// WorldModel: a world description shared by the handles of its elements.
struct PyWorld {
  std::shared_ptr<core::WorldDesc> desc = std::make_shared<core::WorldDesc>();
};
/// RobotModel, RigidObjectModel, TerrainModel: an element of a world by index.
struct PyElement {
  std::shared_ptr<core::WorldDesc> desc;
  int index = 0;
};
struct PyRobot : PyElement {};
struct PyRigidObject : PyElement {};
struct PyTerrain : PyElement {};
/// RobotModelLink.
struct PyLink {
  std::shared_ptr<core::WorldDesc> desc;
  int robot = 0;
  int link = 0;
};

/// Simulator: its own Simulator, or (in a batch run's callbacks) the run's, valid while the
/// callback runs.
struct PySim {
  std::shared_ptr<core::WorldDesc> desc;  ///< the world model it was built from (getWorld)
  std::unique_ptr<core::Simulator> owned;
  core::Simulator* sim = nullptr;
  core::StepStatus status = core::StepStatus::kNormal;  ///< of the last simulate call
  /// The simulator; RuntimeError for a batch run's simulator after its run ended. Inline: the
  /// other extension modules (_render, _window) take Simulators too.
  core::Simulator& get() const {
    if (sim == nullptr) throw std::runtime_error("the simulator of a batch run that has ended");
    return *sim;
  }
};
struct PyBody {
  std::shared_ptr<PySim> sim;
  int id = 0;
};
struct PyController {
  std::shared_ptr<PySim> sim;
  int robot = 0;
};

/// A robot's sensor in a simulation (bind_sensor.cpp).
struct PySensor {
  std::shared_ptr<PySim> sim;
  int robot = 0;
  int index = 0;
};

// ---- conversions (convert.cpp) ------------------------------------------------------------
/// Every number of a number or (nested) sequence, e.g. a numpy array or Klamp't's (R, t).
std::vector<double> Flatten(py::handle value);
core::VecX ToVecX(py::handle value);
/// Exactly three numbers; ValueError naming `what` otherwise.
core::Vec3 ToVec3(py::handle value, const char* what);
py::list ToList(const core::VecX& v);
py::list ToList(const core::Vec3& v);
py::list ToList(const std::vector<double>& v);
/// Klamp't's se3 layout: (R as 9 numbers column-major, t).
py::tuple PoseToPy(const core::Pose& pose);
/// From (R, t) or 12 numbers in that order; ValueError for a matrix that is not a rotation.
core::Pose PoseFromPy(py::handle value);
/// A world id: an int, or a model (anything with getID()).
int ElementId(py::handle element);
/// A robot index: an int, a name, or a RobotModel.
int RobotIndex(const core::WorldDesc& world, py::handle robot);
/// A value read by an access path as Klamp't returns it: a number for one component, (R, t)
/// for a pose, a list otherwise.
py::object AccessValueToPy(const core::AccessTarget& target, const std::vector<double>& value);

void BindWorld(py::module_& m);
void BindSim(py::module_& m);
void BindController(py::module_& m);
void BindSensor(py::module_& m);
void BindBatch(py::module_& m);
void BindTrajectory(py::module_& m);

}  // namespace lamina::python

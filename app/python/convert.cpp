// SPDX-License-Identifier: MIT
// Python values <-> the core's types, and the module's entry point.
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "app/python/bindings.h"

namespace lamina::python {

namespace {

void FlattenInto(py::handle value, std::vector<double>* out) {
  if (py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value)) {
    throw py::value_error("expected numbers, got a string");
  }
  if (py::hasattr(value, "__iter__")) {
    for (py::handle item : py::iter(value)) FlattenInto(item, out);
    return;
  }
  out->push_back(value.cast<double>());
}

}  // namespace

std::vector<double> Flatten(py::handle value) {
  std::vector<double> out;
  FlattenInto(value, &out);
  return out;
}

core::VecX ToVecX(py::handle value) {
  const std::vector<double> v = Flatten(value);
  return Eigen::Map<const core::VecX>(v.data(), static_cast<Eigen::Index>(v.size()));
}

core::Vec3 ToVec3(py::handle value, const char* what) {
  const std::vector<double> v = Flatten(value);
  if (v.size() != 3) {
    throw py::value_error(std::string(what) + " needs 3 numbers, got " + std::to_string(v.size()));
  }
  return core::Vec3(v[0], v[1], v[2]);
}

py::list ToList(const core::VecX& v) {
  py::list out(static_cast<size_t>(v.size()));
  for (Eigen::Index i = 0; i < v.size(); ++i) out[static_cast<size_t>(i)] = v[i];
  return out;
}

py::list ToList(const core::Vec3& v) {
  return ToList(core::VecX(v));
}

py::list ToList(const std::vector<double>& v) {
  py::list out(v.size());
  for (size_t i = 0; i < v.size(); ++i) out[i] = v[i];
  return out;
}

py::tuple PoseToPy(const core::Pose& pose) {
  py::list r(9);
  const core::Mat3 rotation = pose.linear();
  for (int c = 0; c < 3; ++c) {
    for (int row = 0; row < 3; ++row) r[static_cast<size_t>(3 * c + row)] = rotation(row, c);
  }
  return py::make_tuple(r, ToList(core::Vec3(pose.translation())));
}

core::Pose PoseFromPy(py::handle value) {
  const std::vector<double> v = Flatten(value);
  if (v.size() != 12) {
    throw py::value_error("a transform needs (R, t): 9 + 3 numbers, got " +
                          std::to_string(v.size()));
  }
  core::Mat3 rotation;
  for (int c = 0; c < 3; ++c) {
    for (int row = 0; row < 3; ++row) rotation(row, c) = v[static_cast<size_t>(3 * c + row)];
  }
  for (double x : v) {
    if (!std::isfinite(x)) throw py::value_error("a transform must be finite");
  }
  if ((rotation.transpose() * rotation - core::Mat3::Identity()).norm() > 1e-6 ||
      rotation.determinant() < 0) {
    throw py::value_error("R is not a rotation matrix (column-major, 9 numbers)");
  }
  core::Pose pose = core::Pose::Identity();
  pose.linear() = rotation;
  pose.translation() = core::Vec3(v[9], v[10], v[11]);
  return pose;
}

int ElementId(py::handle element) {
  if (py::isinstance<py::int_>(element)) return element.cast<int>();
  if (py::hasattr(element, "getID")) return element.attr("getID")().cast<int>();
  throw py::type_error("expected a world id or a model with getID()");
}

int RobotIndex(const core::WorldDesc& world, py::handle robot) {
  const int count = static_cast<int>(world.robots.size());
  int index = -1;
  if (py::isinstance<py::int_>(robot)) {
    index = robot.cast<int>();
  } else if (py::isinstance<py::str>(robot)) {
    const std::string name = robot.cast<std::string>();
    for (int r = 0; r < count; ++r) {
      if (world.robots[static_cast<size_t>(r)].name == name) index = r;
    }
    if (index < 0) throw py::key_error("no robot is named '" + name + "'");
  } else if (py::isinstance<PyRobot>(robot)) {
    index = robot.cast<const PyRobot&>().index;
  } else {
    throw py::type_error("expected a robot index, name or RobotModel");
  }
  if (index < 0 || index >= count) {
    throw py::index_error("robot " + std::to_string(index) + ": the world has " +
                          std::to_string(count) + " robot(s)");
  }
  return index;
}

py::object AccessValueToPy(const core::AccessTarget& target, const std::vector<double>& value) {
  const core::ParamType type = target.row != nullptr ? target.row->type : core::ParamType::kVector;
  const double first = value.empty() ? 0.0 : value[0];
  if (target.component >= 0) return py::float_(first);
  switch (type) {
    case core::ParamType::kBool:
      return py::bool_(first != 0);
    case core::ParamType::kInteger:
    case core::ParamType::kChoice:
      return py::int_(static_cast<long long>(first));
    case core::ParamType::kReal:
      return py::float_(first);
    case core::ParamType::kPose:
      if (value.size() == 12) {
        return py::make_tuple(ToList(std::vector<double>(value.begin(), value.begin() + 9)),
                              ToList(std::vector<double>(value.begin() + 9, value.end())));
      }
      break;
    default:
      break;
  }
  return ToList(value);
}

}  // namespace lamina::python

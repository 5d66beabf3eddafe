// SPDX-License-Identifier: MIT
// JointLimits construction and validation (see joint_limits.h).
#include "core/control/joint_limits.h"

#include <cmath>

#include "core/diagnostics.h"
namespace lamina::core {
namespace {

bool HasNaN(const VecX& v) {
  return v.array().isNaN().any();
}

}  // namespace

JointLimits JointLimits::Unbounded(int dof, double velocity_max, double acceleration_max) {
  JointLimits limits;
  limits.q_min = VecX::Constant(dof, -kInf);
  limits.q_max = VecX::Constant(dof, kInf);
  limits.velocity_max = VecX::Constant(dof, velocity_max);
  limits.acceleration_max = VecX::Constant(dof, acceleration_max);
  return limits;
}

bool JointLimits::IsValid(int dof, std::string* error) const {
  const std::string expected = std::to_string(dof);
  if (q_min.size() != dof || q_max.size() != dof || velocity_max.size() != dof ||
      acceleration_max.size() != dof) {
    return FailWith(error, "joint limits have sizes q_min " + std::to_string(q_min.size()) +
                               ", q_max " + std::to_string(q_max.size()) + ", velocity_max " +
                               std::to_string(velocity_max.size()) + ", acceleration_max " +
                               std::to_string(acceleration_max.size()) + "; expected " + expected);
  }
  if (HasNaN(q_min) || HasNaN(q_max) || HasNaN(velocity_max) || HasNaN(acceleration_max)) {
    return FailWith(error, "joint limits contain NaN");
  }
  for (int i = 0; i < dof; ++i) {
    if (q_min[i] > q_max[i]) {
      return FailWith(error, "joint " + std::to_string(i) + ": q_min " + std::to_string(q_min[i]) +
                                 " > q_max " + std::to_string(q_max[i]));
    }
    if (velocity_max[i] < 0 || acceleration_max[i] < 0) {
      return FailWith(error,
                      "joint " + std::to_string(i) + ": negative velocity or acceleration limit");
    }
  }
  return true;
}

}  // namespace lamina::core

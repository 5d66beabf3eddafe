// SPDX-License-Identifier: MIT
// The joint bookkeeping of a simulated robot that belongs to a simulation state: restoring it
// with the bodies reproduces the same joint readings bit for bit.
#pragma once

#include <vector>

namespace lamina::core {

struct RobotJointState {
  std::vector<int> turns;  ///< per link: whole turns of a revolute joint past the hinge's range
  std::vector<double> last_angle;  ///< per link: hinge angle at the last accepted step
  bool operator==(const RobotJointState&) const = default;
};

}  // namespace lamina::core

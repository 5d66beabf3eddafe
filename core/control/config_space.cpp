// SPDX-License-Identifier: MIT
#include "core/control/config_space.h"

#include "core/control/angles.h"

namespace lamina::core {

namespace {

bool IsSpinLink(const RobotDesc& robot, int link) {
  for (const JointDesc& joint : robot.joints) {
    if (joint.type == JointType::kSpin && joint.link == link) return true;
  }
  return false;
}

}  // namespace

VecX ConfigDifference(const RobotDesc& robot, const VecX& a, const VecX& b) {
  VecX d = b - a;
  for (int i = 0; i < d.size(); ++i) {
    if (IsSpinLink(robot, i)) d[i] = AngleDiff(b[i], a[i]);
  }
  return d;
}

VecX InterpolateConfig(const RobotDesc& robot, const VecX& a, const VecX& b, double u) {
  VecX x = a + u * ConfigDifference(robot, a, b);
  for (int i = 0; i < x.size(); ++i) {
    if (IsSpinLink(robot, i)) x[i] = NormalizeAngle(x[i]);
  }
  return x;
}

}  // namespace lamina::core

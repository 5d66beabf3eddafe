// SPDX-License-Identifier: MIT
#include "core/sim/robot_guard.h"

#include <algorithm>

namespace lamina::core {

namespace {

constexpr double kBreakGapFloor = 0.01;    // m
constexpr double kBreakGapFraction = 0.1;  // of the link's offset from its parent

}  // namespace

void RobotJointGaps(const RobotDesc& robot, const std::vector<Pose>& frames,
                    const std::vector<char>& known, std::vector<double>* gaps) {
  gaps->assign(robot.dof(), 0.0);
  for (int l = 0; l < robot.dof(); ++l) {
    const LinkDesc& link = robot.links[l];
    if (!known[l] || (link.parent >= 0 && !known[link.parent])) continue;
    const Pose parent = link.parent >= 0 ? frames[link.parent] : Pose::Identity();
    Vec3 gap = frames[l].translation() - parent * link.parent_transform.translation();
    if (link.axis_type == LinkJointAxis::kPrismatic) {
      const Vec3 axis = (frames[l].linear() * link.axis).normalized();
      gap -= gap.dot(axis) * axis;
    }
    (*gaps)[l] = gap.norm();
  }
}

double JointBreakGap(const LinkDesc& link) {
  return std::max(kBreakGapFloor, kBreakGapFraction * link.parent_transform.translation().norm());
}

bool RobotJointsBroke(const RobotDesc& robot, const std::vector<double>& before,
                      const std::vector<double>& after) {
  for (int l = 0; l < robot.dof(); ++l) {
    if (after[l] - before[l] > JointBreakGap(robot.links[l])) return true;
  }
  return false;
}

}  // namespace lamina::core

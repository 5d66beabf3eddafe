// SPDX-License-Identifier: MIT
#include "core/sim/robot_guard.h"

#include <algorithm>

#include "core/sim/joint_projection.h"

namespace lamina::core {

void RobotJointGaps(const RobotDesc& robot, const std::vector<Pose>& frames,
                    const std::vector<char>& known, std::vector<double>* gaps) {
  gaps->assign(robot.dof(), 0.0);
  for (int l = 0; l < robot.dof(); ++l) {
    const LinkDesc& link = robot.links[l];
    if (!known[l] || (link.parent >= 0 && !known[link.parent])) continue;
    const Pose parent = link.parent >= 0 ? frames[link.parent] : Pose::Identity();
    Vec3 gap = frames[l].translation() - parent * link.parent_transform.translation();
    if (link.axis_type == LinkJointAxis::kPrismatic) {
      // the travel within the limits is the joint's; beyond them the stop is open
      const Vec3 axis = (frames[l].linear() * link.axis).normalized();
      gap -= std::min(std::max(gap.dot(axis), link.q_min), link.q_max) * axis;
    }
    (*gaps)[l] = gap.norm();
  }
}

double JointBreakGap(const LinkDesc& link) {
  return JointBreakGap(link.parent_transform.translation().norm());
}

bool RobotJointsBroke(const RobotDesc& robot, const std::vector<double>& before,
                      const std::vector<double>& after) {
  for (int l = 0; l < robot.dof(); ++l) {
    if (after[l] - before[l] > JointBreakGap(robot.links[l])) return true;
  }
  return false;
}

bool RobotJointsOpen(const RobotDesc& robot, const std::vector<double>& gaps, double* largest) {
  bool open = false;
  for (int l = 0; l < robot.dof(); ++l) {
    open = open || gaps[l] > JointBreakGap(robot.links[l]);
    if (largest) *largest = std::max(*largest, gaps[l]);
  }
  return open;
}

}  // namespace lamina::core

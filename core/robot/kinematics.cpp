// SPDX-License-Identifier: MIT
#include "core/robot/kinematics.h"

#include <stdexcept>
#include <string>

namespace lamina::core {

Pose LinkJointMotion(const LinkDesc& link, double q) {
  Pose motion = Pose::Identity();
  if (link.axis_type == LinkJointAxis::kRevolute) {
    motion.linear() = Eigen::AngleAxisd(q, link.axis.normalized()).toRotationMatrix();
  } else {
    motion.translation() = q * link.axis;
  }
  return motion;
}

std::vector<Pose> LinkTransforms(const RobotDesc& robot, const VecX& q) {
  if (q.size() != robot.dof()) {
    throw std::invalid_argument("robot '" + robot.name + "' has " + std::to_string(robot.dof()) +
                                " links, configuration has " + std::to_string(q.size()));
  }
  std::vector<Pose> frames(robot.links.size(), Pose::Identity());
  for (size_t i = 0; i < robot.links.size(); ++i) {
    const LinkDesc& link = robot.links[i];
    const Pose parent = link.parent >= 0 ? frames[link.parent] : Pose::Identity();
    frames[i] = parent * link.parent_transform * LinkJointMotion(link, q[static_cast<int>(i)]);
  }
  return frames;
}

std::vector<Vec3> LinkComPositions(const RobotDesc& robot, const std::vector<Pose>& frames) {
  std::vector<Vec3> coms(frames.size());
  for (size_t i = 0; i < frames.size(); ++i) coms[i] = frames[i] * robot.links[i].com;
  return coms;
}

}  // namespace lamina::core

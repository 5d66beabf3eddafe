// SPDX-License-Identifier: MIT
#include "core/robot/floating_base.h"

#include <algorithm>

#include <Eigen/Dense>

#include "core/robot/kinematics.h"

namespace lamina::core {

namespace {

constexpr int kIterations = 30;
constexpr double kTolerance = 1e-9;
constexpr double kDelta = 1e-7;  // finite-difference step, m or rad

// position error and rotation error (the moment from the frame's rotation to the target's)
Eigen::Matrix<double, 6, 1> Residual(const RobotDesc& robot, int link, const VecX& q,
                                     const Pose& target) {
  const Pose frame = LinkTransforms(robot, q)[link];
  Eigen::Matrix<double, 6, 1> r;
  r.head<3>() = frame.translation() - target.translation();
  r.tail<3>() = MomentFromRotation(target.linear().transpose() * frame.linear());
  return r;
}

}  // namespace

std::vector<int> FloatingBaseLinks(const RobotDesc& robot) {
  for (const JointDesc& joint : robot.joints) {
    if (joint.type != JointType::kFloating || joint.base != -1) continue;
    std::vector<int> chain;
    for (int link = joint.link; link >= 0; link = robot.links[link].parent) chain.push_back(link);
    if (chain.size() != 6) return {};
    std::reverse(chain.begin(), chain.end());
    return chain;
  }
  return {};
}

std::optional<VecX> PlaceFloatingBase(const RobotDesc& robot, const std::vector<int>& links,
                                      const VecX& q, const Pose& target) {
  if (links.size() != 6 || q.size() != robot.dof()) return std::nullopt;
  VecX x = q;
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    const Eigen::Matrix<double, 6, 1> r = Residual(robot, links.back(), x, target);
    if (r.norm() < kTolerance) return x;
    Eigen::Matrix<double, 6, 6> jacobian;
    for (int k = 0; k < 6; ++k) {
      VecX moved = x;
      moved[links[k]] += kDelta;
      jacobian.col(k) = (Residual(robot, links.back(), moved, target) - r) / kDelta;
    }
    const Eigen::Matrix<double, 6, 1> step = jacobian.colPivHouseholderQr().solve(-r);
    if (!step.allFinite()) return std::nullopt;
    for (int k = 0; k < 6; ++k) x[links[k]] += step[k];
  }
  if (Residual(robot, links.back(), x, target).norm() < kTolerance) return x;
  return std::nullopt;
}

}  // namespace lamina::core

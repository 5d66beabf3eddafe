// SPDX-License-Identifier: MIT
// Potential energy and gravity torques by subtree mass accumulation (see dynamics.h).
#include "core/robot/dynamics.h"

#include <vector>

#include "core/robot/kinematics.h"

namespace lamina::core {

double PotentialEnergy(const RobotDesc& robot, const VecX& q, const Vec3& gravity) {
  const std::vector<Vec3> coms = LinkComPositions(robot, LinkTransforms(robot, q));
  double energy = 0;
  for (size_t k = 0; k < coms.size(); ++k) energy -= robot.links[k].mass * gravity.dot(coms[k]);
  return energy;
}

VecX GravityTorques(const RobotDesc& robot, const VecX& q, const Vec3& gravity) {
  const std::vector<Pose> frames = LinkTransforms(robot, q);
  const std::vector<Vec3> coms = LinkComPositions(robot, frames);
  const int n = robot.dof();
  // Subtree mass M_i and first moment C_i = Σ m_k p_k; parents precede children, so a backward
  // sweep sees every child before its parent.
  std::vector<double> mass(n, 0.0);
  std::vector<Vec3> moment(n, Vec3::Zero());
  for (int i = n - 1; i >= 0; --i) {
    mass[i] += robot.links[i].mass;
    moment[i] += robot.links[i].mass * coms[i];
    const int parent = robot.links[i].parent;
    if (parent >= 0) {
      mass[parent] += mass[i];
      moment[parent] += moment[i];
    }
  }
  VecX torques = VecX::Zero(n);
  for (int i = 0; i < n; ++i) {
    const LinkDesc& link = robot.links[i];
    if (link.axis_type == LinkJointAxis::kPrismatic) {
      // ∂p_k/∂q_i = R_i·axis for every k in the subtree (kinematics uses the axis unnormalized)
      torques[i] = -mass[i] * gravity.dot(frames[i].linear() * link.axis);
    } else {
      const Vec3 axis = frames[i].linear() * link.axis.normalized();
      // ∂p_k/∂q_i = axis × (p_k − o_i), summed with weights m_k
      const Vec3 lever = moment[i] - mass[i] * frames[i].translation();
      torques[i] = -gravity.dot(axis.cross(lever));
    }
  }
  return torques;
}

}  // namespace lamina::core

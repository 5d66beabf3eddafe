// SPDX-License-Identifier: MIT
// Potential energy and gravity torques by subtree mass accumulation (see dynamics.h).
#include "core/robot/dynamics.h"

#include <algorithm>
#include <vector>

#include <Eigen/Cholesky>

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

namespace {

bool IsAncestorOrSelf(const RobotDesc& robot, int ancestor, int link) {
  for (int k = link; k >= 0; k = robot.links[k].parent) {
    if (k == ancestor) return true;
  }
  return false;
}

// the velocity of a world point carried by link `link` per unit rate of joint i (3 x n)
MatX PointJacobian(const RobotDesc& robot, const std::vector<Pose>& frames,
                   const std::vector<bool>& free, int link, const Vec3& point) {
  MatX jacobian = MatX::Zero(3, robot.dof());
  for (int i = 0; i < robot.dof(); ++i) {
    if (!free[i] || !IsAncestorOrSelf(robot, i, link)) continue;
    const LinkDesc& joint = robot.links[i];
    const Vec3 axis = frames[i].linear() * joint.axis.normalized();
    jacobian.col(i) = joint.axis_type == LinkJointAxis::kPrismatic
                          ? axis
                          : Vec3(axis.cross(point - frames[i].translation()));
  }
  return jacobian;
}

// the angular velocity of link `link` per unit rate of joint i (3 x n)
MatX RotationJacobian(const RobotDesc& robot, const std::vector<Pose>& frames,
                      const std::vector<bool>& free, int link) {
  MatX jacobian = MatX::Zero(3, robot.dof());
  for (int i = 0; i < robot.dof(); ++i) {
    if (!free[i] || !IsAncestorOrSelf(robot, i, link)) continue;
    if (robot.links[i].axis_type == LinkJointAxis::kPrismatic) continue;
    jacobian.col(i) = frames[i].linear() * robot.links[i].axis.normalized();
  }
  return jacobian;
}

}  // namespace

MatX MassMatrix(const RobotDesc& robot, const VecX& q, const std::vector<bool>& free) {
  const std::vector<Pose> frames = LinkTransforms(robot, q);
  const std::vector<Vec3> coms = LinkComPositions(robot, frames);
  const int n = robot.dof();
  MatX mass = MatX::Zero(n, n);
  for (int k = 0; k < n; ++k) {
    const LinkDesc& link = robot.links[k];
    if (link.mass <= 0.0 && link.inertia.isZero(0.0)) continue;
    const MatX linear = PointJacobian(robot, frames, free, k, coms[k]);
    const MatX angular = RotationJacobian(robot, frames, free, k);
    const Mat3 rotation = frames[k].linear();
    const Mat3 inertia = rotation * link.inertia * rotation.transpose();
    mass += link.mass * linear.transpose() * linear + angular.transpose() * inertia * angular;
  }
  return mass;
}

namespace {

// M with a tiny armature on its diagonal (returned in `armature`): joints that move nothing with
// mass (or are not free) would make M singular; the armature keeps it invertible without changing
// what the masses say
MatX InvertibleMassMatrix(const RobotDesc& robot, const VecX& q, const std::vector<bool>& free,
                          double* armature) {
  MatX mass = MassMatrix(robot, q, free);
  *armature = 1e-9 * std::max(1.0, mass.diagonal().cwiseAbs().maxCoeff());
  mass.diagonal().array() += *armature;
  return mass;
}

// 3 / trace(J M⁻¹ Jᵀ) for a 3 x n Jacobian; inf when J moves nothing
double ThreeOverTrace(const RobotDesc& robot, const VecX& q, const std::vector<bool>& free,
                      const MatX& jacobian) {
  if (jacobian.isZero(0.0)) return kInf;
  double armature = 0.0;
  const MatX solved =
      InvertibleMassMatrix(robot, q, free, &armature).ldlt().solve(jacobian.transpose());
  const double trace = (jacobian * solved).trace();
  return trace > 0.0 ? 3.0 / trace : kInf;
}

}  // namespace

VecX JointInertias(const RobotDesc& robot, const VecX& q, const std::vector<bool>& free) {
  const int n = robot.dof();
  VecX inertias = VecX::Constant(n, kInf);
  double armature = 0.0;
  const MatX inverse =
      InvertibleMassMatrix(robot, q, free, &armature).ldlt().solve(MatX::Identity(n, n));
  for (int i = 0; i < n; ++i) {
    const double moved = 1.0 / inverse(i, i) - armature;
    if (free[i] && moved > armature) inertias[i] = moved;
  }
  return inertias;
}

double EffectiveMassAt(const RobotDesc& robot, const VecX& q, const std::vector<bool>& free,
                       int link, const Vec3& point) {
  return ThreeOverTrace(robot, q, free,
                        PointJacobian(robot, LinkTransforms(robot, q), free, link, point));
}

double EffectiveInertiaOf(const RobotDesc& robot, const VecX& q, const std::vector<bool>& free,
                          int link) {
  return ThreeOverTrace(robot, q, free,
                        RotationJacobian(robot, LinkTransforms(robot, q), free, link));
}

}  // namespace lamina::core

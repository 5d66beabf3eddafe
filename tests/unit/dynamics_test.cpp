// SPDX-License-Identifier: MIT
// Gravity torques against central differences of the potential energy, on a 3-link arm with a
// prismatic joint, tilted axes and offset COMs, and on a branching tree; the inertia each joint
// moves.
#include "core/robot/dynamics.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace lamina::core {
namespace {

LinkDesc Link(int parent, LinkJointAxis type, const Vec3& axis, const Vec3& offset, double mass,
              const Vec3& com) {
  LinkDesc link;
  link.parent = parent;
  link.axis_type = type;
  link.axis = axis;
  link.parent_transform = Pose::Identity();
  link.parent_transform.linear() = RotationFromRollPitchYaw(0.1 * parent, 0.2, -0.3);
  link.parent_transform.translation() = offset;
  link.mass = mass;
  link.com = com;
  return link;
}

RobotDesc ThreeLinkArm() {
  RobotDesc robot;
  const auto r = LinkJointAxis::kRevolute;
  robot.links.push_back(Link(-1, r, Vec3(0, 0, 1), Vec3(0, 0, 0.1), 3.0, Vec3(0.01, 0, 0.05)));
  robot.links.push_back(
      Link(0, r, Vec3(0, 1, 1).normalized(), Vec3(0, 0.1, 0.3), 2.0, Vec3(0.2, 0.02, 0)));
  robot.links.push_back(
      Link(1, LinkJointAxis::kPrismatic, Vec3(1, 0, 0.5), Vec3(0.4, 0, 0), 1.5, Vec3(0.1, 0, 0)));
  return robot;
}

VecX NumericGradient(const RobotDesc& robot, const VecX& q, const Vec3& gravity) {
  const double step = 1e-6;
  VecX gradient(q.size());
  for (int i = 0; i < q.size(); ++i) {
    VecX plus = q, minus = q;
    plus[i] += step;
    minus[i] -= step;
    gradient[i] = (PotentialEnergy(robot, plus, gravity) - PotentialEnergy(robot, minus, gravity)) /
                  (2 * step);
  }
  return gradient;
}

void ExpectGradientMatches(const RobotDesc& robot, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> angle(-3.0, 3.0);
  const Vec3 gravity(0.3, -0.2, -9.8);
  for (int trial = 0; trial < 20; ++trial) {
    VecX q(robot.dof());
    for (int i = 0; i < q.size(); ++i) q[i] = angle(rng);
    const VecX analytic = GravityTorques(robot, q, gravity);
    const VecX numeric = NumericGradient(robot, q, gravity);
    ASSERT_EQ(analytic.size(), robot.dof());
    for (int i = 0; i < q.size(); ++i) {
      EXPECT_NEAR(analytic[i], numeric[i], 1e-6) << "trial " << trial << " joint " << i;
    }
  }
}

TEST(DynamicsTest, GravityTorquesAreThePotentialEnergyGradient) {
  ExpectGradientMatches(ThreeLinkArm(), 7);
}

TEST(DynamicsTest, GravityTorquesOnABranchingTree) {
  RobotDesc robot = ThreeLinkArm();
  robot.links.push_back(
      Link(0, LinkJointAxis::kRevolute, Vec3(1, 0, 0), Vec3(0, -0.2, 0.2), 0.7, Vec3(0, 0.1, 0.1)));
  robot.links.push_back(
      Link(3, LinkJointAxis::kRevolute, Vec3(0, 1, 0), Vec3(0, 0, 0.3), 0.4, Vec3(0.05, 0, 0.1)));
  ExpectGradientMatches(robot, 11);
}

TEST(DynamicsTest, HorizontalPendulumTorque) {
  RobotDesc robot;
  robot.links.push_back(
      Link(-1, LinkJointAxis::kRevolute, Vec3(0, 1, 0), Vec3::Zero(), 2.0, Vec3(0.5, 0, 0)));
  robot.links[0].parent_transform = Pose::Identity();
  // Holding a 2 kg mass 0.5 m out horizontally about +y: the link sags towards +x → −z, which
  // is a positive rotation about +y; the holding torque is −m·g·l = −9.8.
  const VecX tau = GravityTorques(robot, VecX::Zero(1), Vec3(0, 0, -9.8));
  EXPECT_NEAR(tau[0], -9.8, 1e-12);
}

TEST(DynamicsTest, WrongSizeThrows) {
  EXPECT_THROW(GravityTorques(ThreeLinkArm(), VecX::Zero(2), Vec3(0, 0, -9.8)),
               std::invalid_argument);
}

// two sliders along the same axis, m1 then m2 on it: with the other joint free, the first joint
// moves m1 alone (the second lets m2 stay) and the second the reduced mass m1·m2 / (m1 + m2)
// (it pushes m2 against m1)
TEST(DynamicsTest, JointInertiasAreWhatEachJointMovesWithTheOthersFree) {
  RobotDesc robot;
  const auto p = LinkJointAxis::kPrismatic;
  robot.links.push_back(Link(-1, p, Vec3::UnitX(), Vec3::Zero(), 3.0, Vec3::Zero()));
  robot.links.push_back(Link(0, p, Vec3::UnitX(), Vec3::Zero(), 2.0, Vec3::Zero()));
  for (LinkDesc& link : robot.links) link.parent_transform = Pose::Identity();
  const VecX inertias = JointInertias(robot, VecX::Zero(2), {true, true});
  EXPECT_NEAR(inertias[0], 3.0, 1e-6);
  EXPECT_NEAR(inertias[1], 3.0 * 2.0 / 5.0, 1e-6);
  // the first joint welded: the second pushes m2 alone
  const VecX welded = JointInertias(robot, VecX::Zero(2), {false, true});
  EXPECT_TRUE(std::isinf(welded[0]));
  EXPECT_NEAR(welded[1], 2.0, 1e-6);
}

}  // namespace
}  // namespace lamina::core

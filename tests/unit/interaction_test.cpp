// SPDX-License-Identifier: MIT
// The mouse spring's and the turn drag's pure parts (interaction.h) and the effective mass at a
// point (MuJoCo's 3 / trace(J M⁻¹ Jᵀ)) and rotational effective inertia (3 / trace(J_ω M⁻¹ J_ωᵀ))
// of a free rigid body and of robots (core/robot/dynamics.h).
#include "core/sim/interaction.h"

#include <gtest/gtest.h>

#include "core/robot/dynamics.h"

namespace lamina::core {
namespace {

TEST(DragSpringTest, StiffnessAndDampingScaleWithTheMassAtTheGrabbedPoint) {
  const DragSpringSettings settings;  // 5 Hz, critically damped, 20 m g, 0.5 m
  const DragSpring light = MakeDragSpring(0.1, 9.8, settings);
  const DragSpring heavy = MakeDragSpring(100.0, 9.8, settings);
  const double omega = 2 * kPi * 5.0;
  EXPECT_DOUBLE_EQ(light.stiffness, 0.1 * omega * omega);
  EXPECT_DOUBLE_EQ(light.damping, 2 * 0.1 * omega);  // ζ = c / (2 √(k m)) = 1
  EXPECT_DOUBLE_EQ(light.max_force, 20 * 0.1 * 9.8);
  EXPECT_DOUBLE_EQ(heavy.stiffness / light.stiffness, 1000.0);
  EXPECT_DOUBLE_EQ(heavy.max_force / light.max_force, 1000.0);
  // without gravity the cap still means something
  EXPECT_DOUBLE_EQ(MakeDragSpring(1.0, 0.0, settings).max_force, 20 * 9.81);
}

TEST(DragSpringTest, TheScaleKeepsTheImplicitForceBoundUnderTheCap) {
  const DragSpring spring{1000.0, 60.0, 100.0};
  const Vec3 g(0, 0, -9.8);
  // small stretch at rest: k|e| + (k h + c)|h g| = 10 + 61·0.0098 under 100
  EXPECT_EQ(DragScale(spring, Vec3(0.01, 0, 0), Vec3::Zero(), g, 0.001), 1.0);
  // flung far: the bound is brought exactly to the cap
  const Vec3 stretch(0.3, 0, 0), velocity(0, 2.0, 0);
  const double scale = DragScale(spring, stretch, velocity, g, 0.001);
  const double bound =
      scale * (1000.0 * 0.3 + (1000.0 * 0.001 + 60.0) * (velocity + 0.001 * g).norm());
  EXPECT_LT(scale, 1.0);
  EXPECT_NEAR(bound, 100.0, 1e-9);
}

TEST(DragSpringTest, TheTargetIsHeldWithinTheMaximumStretch) {
  const Vec3 point(1, 2, 3);
  EXPECT_EQ(CapStretch(point, Vec3(1, 2, 3.2), 0.5), Vec3(1, 2, 3.2));
  const Vec3 capped = CapStretch(point, Vec3(1, 2, 13), 0.5);
  EXPECT_NEAR((capped - Vec3(1, 2, 3.5)).norm(), 0.0, 1e-15);
}

TEST(TurnSpringTest, StiffnessDampingAndCapScaleWithTheInertia) {
  const DragSpringSettings settings;  // 5 Hz, critically damped, 20 m g
  const double omega = 2 * kPi * 5.0;
  const TurnSpring spring = MakeTurnSpring(0.02, 3.0, 9.8, settings);
  EXPECT_DOUBLE_EQ(spring.stiffness, 0.02 * omega * omega);  // N·m/rad
  EXPECT_DOUBLE_EQ(spring.damping, 2 * 0.02 * omega);        // ζ = c / (2 √(k I)) = 1
  // the force cap 20 m g at the radius of gyration √(I/m)
  EXPECT_DOUBLE_EQ(spring.max_torque, 20 * 3.0 * 9.8 * std::sqrt(0.02 / 3.0));
  EXPECT_DOUBLE_EQ(MakeTurnSpring(0.02, 3.0, 0.0, settings).max_torque,
                   20 * 9.81 * std::sqrt(0.06));
}

TEST(TurnSpringTest, TheScaleKeepsTheImplicitTorqueBoundUnderTheCap) {
  const TurnSpring spring{10.0, 0.6, 2.0};
  EXPECT_EQ(TurnScale(spring, Vec3(0.1, 0, 0), Vec3::Zero(), 0.001), 1.0);  // 1 N·m < 2
  const Vec3 turn(0, 0, 1.0), spin(3.0, 0, 0);
  const double scale = TurnScale(spring, turn, spin, 0.001);
  EXPECT_NEAR(scale * (10.0 * 1.0 + (10.0 * 0.001 + 0.6) * 3.0), 2.0, 1e-12);
}

TEST(TurnSpringTest, TheTurnIsTheLogarithmShortenedToTheCap) {
  const Mat3 from = Eigen::AngleAxisd(0.3, Vec3::UnitX()).toRotationMatrix();
  const Mat3 to = Eigen::AngleAxisd(0.5, Vec3::UnitZ()).toRotationMatrix() * from;
  EXPECT_NEAR((CappedTurn(from, to, kMaxDragTurn) - Vec3(0, 0, 0.5)).norm(), 0.0, 1e-12);
  const Mat3 far = Eigen::AngleAxisd(2.5, Vec3::UnitY()).toRotationMatrix() * from;
  EXPECT_NEAR((CappedTurn(from, far, kMaxDragTurn) - Vec3(0, kPi / 2, 0)).norm(), 0.0, 1e-12);
}

TEST(EffectiveInertiaTest, AFreeBodyHasThreeOverTheTraceOfItsInverseInertia) {
  EXPECT_DOUBLE_EQ(RigidEffectiveInertia(0.5 * Mat3::Identity()), 0.5);
  const Mat3 inertia = Vec3(0.1, 0.2, 0.4).asDiagonal();
  EXPECT_NEAR(RigidEffectiveInertia(inertia), 3 / (10 + 5 + 2.5), 1e-15);
  const Mat3 turned = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  EXPECT_NEAR(RigidEffectiveInertia(turned * inertia * turned.transpose()), 3 / 17.5, 1e-12);
}

TEST(EffectiveMassTest, AFreeBodyHasItsMassAtItsCentreAndLessAwayFromIt) {
  const double m = 2.0, i = 0.1;
  const Mat3 inertia = i * Mat3::Identity();
  EXPECT_DOUBLE_EQ(RigidEffectiveMass(m, inertia, Vec3::Zero()), m);
  // 3 / (3/m + 2 r² / i): the point can also turn about the centre
  const double r = 0.5;
  EXPECT_NEAR(RigidEffectiveMass(m, inertia, Vec3(r, 0, 0)), 3 / (3 / m + 2 * r * r / i), 1e-12);
}

RobotDesc OneLinkRobot(LinkJointAxis axis, double mass, const Mat3& inertia, const Vec3& com) {
  RobotDesc robot;
  LinkDesc link;
  link.axis_type = axis;
  link.axis = Vec3::UnitZ();
  link.mass = mass;
  link.inertia = inertia;
  link.com = com;
  robot.links.push_back(link);
  return robot;
}

TEST(EffectiveMassTest, APendulumPointHasThreeTimesItsScalarInertiaOverLeverSquared) {
  // a point mass m at L on a hinge about z: M = m L², the point moves along one direction only
  const double m = 1.5, L = 0.8;
  const RobotDesc robot = OneLinkRobot(LinkJointAxis::kRevolute, m, Mat3::Zero(), Vec3(L, 0, 0));
  const VecX q = VecX::Zero(1);
  EXPECT_NEAR(MassMatrix(robot, q, {true})(0, 0), m * L * L, 1e-12);
  EXPECT_NEAR(EffectiveMassAt(robot, q, {true}, 0, Vec3(L, 0, 0)), 3 * m, 1e-6);
  // a welded link does not move at all
  EXPECT_EQ(EffectiveMassAt(robot, q, {false}, 0, Vec3(L, 0, 0)), kInf);
}

TEST(EffectiveInertiaTest, AHingedLinkHasThreeTimesItsInertiaAboutTheHinge) {
  const double m = 1.5, L = 0.8, i = 0.02;
  const RobotDesc robot =
      OneLinkRobot(LinkJointAxis::kRevolute, m, i * Mat3::Identity(), Vec3(L, 0, 0));
  const VecX q = VecX::Constant(1, 0.4);
  EXPECT_NEAR(EffectiveInertiaOf(robot, q, {true}, 0), 3 * (i + m * L * L), 1e-6);
  EXPECT_EQ(EffectiveInertiaOf(robot, q, {false}, 0), kInf);
  // a slider cannot turn its link
  const RobotDesc slider =
      OneLinkRobot(LinkJointAxis::kPrismatic, m, i * Mat3::Identity(), Vec3(L, 0, 0));
  EXPECT_EQ(EffectiveInertiaOf(slider, q, {true}, 0), kInf);
}

TEST(EffectiveMassTest, AFloatingBaseMatchesTheFreeBodyFormula) {
  // six virtual links (x, y, z slides, then turns about z, y, x) and a body: Klamp't's base
  RobotDesc robot;
  const Vec3 axes[] = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ(),
                       Vec3::UnitZ(), Vec3::UnitY(), Vec3::UnitX()};
  for (int k = 0; k < 6; ++k) {
    LinkDesc link;
    link.parent = k - 1;
    link.axis = axes[k];
    link.axis_type = k < 3 ? LinkJointAxis::kPrismatic : LinkJointAxis::kRevolute;
    link.mass = 0.0;
    link.inertia = Mat3::Zero();
    robot.links.push_back(link);
  }
  const double m = 3.0;
  const Mat3 inertia = Vec3(0.2, 0.3, 0.4).asDiagonal();
  robot.links.back().mass = m;
  robot.links.back().inertia = inertia;
  VecX q(6);
  q << 0.1, -0.2, 0.5, 0.3, 0.2, -0.4;
  const std::vector<bool> free(6, true);
  const Pose frame =
      Pose(Eigen::Translation3d(Vec3(q.head<3>()))) * Eigen::AngleAxisd(q[3], Vec3::UnitZ()) *
      Eigen::AngleAxisd(q[4], Vec3::UnitY()) * Eigen::AngleAxisd(q[5], Vec3::UnitX());
  const Vec3 point = frame * Vec3(0.1, 0.2, -0.3);
  const Mat3 world_inertia = frame.linear() * inertia * frame.linear().transpose();
  EXPECT_NEAR(EffectiveMassAt(robot, q, free, 5, point),
              RigidEffectiveMass(m, world_inertia, point - frame.translation()), 1e-6);
  EXPECT_NEAR(EffectiveInertiaOf(robot, q, free, 5), RigidEffectiveInertia(inertia), 1e-6);
}

}  // namespace
}  // namespace lamina::core

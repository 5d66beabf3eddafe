// SPDX-License-Identifier: MIT
// A robot's ODE joints as Newton solver rows (core/sim/ode_joint_rows.h), checked by what the
// rows must mean rather than against ODE's code: a hinge's five rows see no velocity of the two
// bodies moving as one, nor a turn about its axis; its stop row measures that turn and pushes
// back at the stop ERP; a motor row is bounded by its fmax; what is not replicated is refused.
#include "core/sim/ode_joint_rows.h"

#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>
#include <ode/ode.h>

#include "core/math_types.h"
#include "core/sim/ode_handle.h"

namespace lamina::core {
namespace {

constexpr double kJointStep = 0.001;

// two bodies 1 m apart on z, in a world of ERP 0.5 and CFM 1e-6
struct TwoBodies {
  OdeWorldPtr owner = CreateOdeWorld();
  dWorldID world = owner.get();
  dBodyID child = dBodyCreate(world);
  dBodyID parent = dBodyCreate(world);
  dJointID hinge = nullptr;

  TwoBodies() {
    dWorldSetERP(world, 0.5);
    dWorldSetCFM(world, 1e-6);
    dBodySetPosition(child, 0.0, 0.0, -0.5);
    dBodySetPosition(parent, 0.0, 0.0, 0.5);
  }

  // a hinge about y through the origin
  void Hinge() {
    hinge = dJointCreateHinge(world, nullptr);
    dJointAttach(hinge, child, parent);
    dJointSetHingeAnchor(hinge, 0.0, 0.0, 0.0);
    dJointSetHingeAxis(hinge, 0.0, 1.0, 0.0);
  }
  // the hinge's axis in the parent's axes, as OdeRobot records it
  static JointFrame HingeFrame() {
    JointFrame frame;
    frame.axis2 = Vec3::UnitY();
    return frame;
  }
};

// the velocity a row sees when the child moves with twist `a` and the parent with `b` (linear
// velocity of the centre of mass, angular velocity)
double Seen(const NewtonRow& row, const Vec6& a, const Vec6& b) {
  return row.ja.dot(a) + (row.b >= 0 ? row.jb.dot(b) : 0.0);
}

// the twist of a body whose centre is at `centre` in a rigid motion (v at the origin, ω)
Vec6 RigidMotion(const Vec3& centre, const Vec3& v, const Vec3& omega) {
  Vec6 twist;
  twist << v + omega.cross(centre), omega;
  return twist;
}

TEST(OdeJointRowsTest, AHingesRowsSeeNoMotionOfBothBodiesTogetherNorATurnAboutItsAxis) {
  TwoBodies bodies;
  bodies.Hinge();
  std::vector<NewtonRow> rows;
  ASSERT_TRUE(
      JointRows(bodies.hinge, 0, 1, TwoBodies::HingeFrame(), bodies.world, kJointStep, &rows));
  ASSERT_EQ(rows.size(), 5u);  // no stops, no motor
  const Vec3 child(0.0, 0.0, -0.5), parent(0.0, 0.0, 0.5);
  const Vec3 v(0.3, -0.2, 0.1), omega(1.0, 2.0, -0.5);
  for (const NewtonRow& row : rows) {
    EXPECT_EQ(row.a, 0);
    EXPECT_EQ(row.b, 1);
    EXPECT_EQ(row.lo, -kInf);
    EXPECT_EQ(row.hi, kInf);
    EXPECT_DOUBLE_EQ(row.cfm, 1e-6);
    EXPECT_NEAR(row.rhs, 0.0, 1e-12);  // the joint is where it was built
    // both bodies in one rigid motion
    EXPECT_NEAR(Seen(row, RigidMotion(child, v, omega), RigidMotion(parent, v, omega)), 0.0, 1e-12);
    // the child turning about the hinge axis through the anchor, the parent still
    EXPECT_NEAR(Seen(row, RigidMotion(child, Vec3::Zero(), 3.0 * Vec3::UnitY()), Vec6::Zero()), 0.0,
                1e-12);
  }
  // and every other motion of the child is seen by some row
  for (const Vec3& omega_child : {Vec3(Vec3::UnitX()), Vec3(Vec3::UnitZ())}) {
    double seen = 0.0;
    for (const NewtonRow& row : rows) {
      seen += std::abs(Seen(row, RigidMotion(child, Vec3::Zero(), omega_child), Vec6::Zero()));
    }
    EXPECT_GT(seen, 0.5);
  }
}

TEST(OdeJointRowsTest, AHingePulledApartIsPulledBackAtTheWorldErp) {
  TwoBodies bodies;
  bodies.Hinge();
  dBodySetPosition(bodies.parent, 0.002, 0.0, 0.5);  // the parent's anchor 2 mm along x
  std::vector<NewtonRow> rows;
  ASSERT_TRUE(
      JointRows(bodies.hinge, 0, 1, TwoBodies::HingeFrame(), bodies.world, kJointStep, &rows));
  // row x: the child's anchor velocity less the parent's, asked to close the gap in 1/ERP steps
  EXPECT_NEAR(rows[0].rhs, 0.5 / kJointStep * 0.002, 1e-9);
  EXPECT_NEAR(rows[1].rhs, 0.0, 1e-12);
  EXPECT_NEAR(rows[2].rhs, 0.0, 1e-12);
}

TEST(OdeJointRowsTest, AHingeBeyondItsStopGetsAOneSidedStopRow) {
  TwoBodies bodies;
  bodies.Hinge();
  dJointSetHingeParam(bodies.hinge, dParamLoStop, -0.1);
  dJointSetHingeParam(bodies.hinge, dParamHiStop, 0.1);
  dJointSetHingeParam(bodies.hinge, dParamStopERP, 0.2);
  std::vector<NewtonRow> rows;
  ASSERT_TRUE(
      JointRows(bodies.hinge, 0, 1, TwoBodies::HingeFrame(), bodies.world, kJointStep, &rows));
  EXPECT_EQ(rows.size(), 5u);  // inside its range
  // the child turned 0.15 rad about the axis (about the anchor, the joint stays together)
  dMatrix3 rotation;
  dRFromAxisAndAngle(rotation, 0.0, 1.0, 0.0, 0.15);
  dBodySetRotation(bodies.child, rotation);
  const double angle = dJointGetHingeAngle(bodies.hinge);
  ASSERT_NEAR(std::abs(angle), 0.15, 1e-12);
  Vec3 centre = Eigen::AngleAxisd(0.15, Vec3::UnitY()) * Vec3(0.0, 0.0, -0.5);
  dBodySetPosition(bodies.child, centre.x(), centre.y(), centre.z());
  rows.clear();
  ASSERT_TRUE(
      JointRows(bodies.hinge, 0, 1, TwoBodies::HingeFrame(), bodies.world, kJointStep, &rows));
  ASSERT_EQ(rows.size(), 6u);
  const NewtonRow& stop = rows.back();
  // it reads the hinge's rate, pushes back 0.2 of the 0.05 rad overrun per step, one-sided
  const double rate = Seen(stop, RigidMotion(centre, Vec3::Zero(), Vec3::UnitY()), Vec6::Zero());
  EXPECT_NEAR(std::abs(rate), 1.0, 1e-12);
  EXPECT_NEAR(stop.rhs, -0.2 / kJointStep * (angle - (angle > 0 ? 0.1 : -0.1)), 1e-9);
  EXPECT_EQ(angle > 0 ? stop.lo : stop.hi, angle > 0 ? -kInf : kInf);
  EXPECT_EQ(angle > 0 ? stop.hi : stop.lo, 0.0);
}

TEST(OdeJointRowsTest, AMotorAxisIsARowBoundedByItsFmax) {
  TwoBodies bodies;
  dJointID motor = dJointCreateAMotor(bodies.world, nullptr);
  dJointAttach(motor, bodies.child, nullptr);  // to the world
  dJointSetAMotorMode(motor, dAMotorUser);
  dJointSetAMotorNumAxes(motor, 2);
  dJointSetAMotorAxis(motor, 0, 1, 0.0, 1.0, 0.0);
  dJointSetAMotorAxis(motor, 1, 1, 0.0, 1.0, 0.0);
  std::vector<NewtonRow> rows;
  ASSERT_TRUE(JointRows(motor, 0, -1, JointFrame{}, bodies.world, kJointStep, &rows));
  EXPECT_TRUE(rows.empty());  // fmax 0: no row
  dJointSetAMotorParam(motor, dParamFMax2, 5.0);
  dJointSetAMotorParam(motor, dParamVel2, 1.5);
  dJointSetAMotorParam(motor, dParamCFM2, 0.01);
  ASSERT_TRUE(JointRows(motor, 0, -1, JointFrame{}, bodies.world, kJointStep, &rows));
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].b, -1);
  EXPECT_EQ(rows[0].ja.tail<3>(), Vec3::UnitY());
  EXPECT_EQ(rows[0].ja.head<3>(), Vec3::Zero());
  EXPECT_DOUBLE_EQ(rows[0].rhs, 1.5);
  EXPECT_DOUBLE_EQ(rows[0].cfm, 0.01);
  EXPECT_DOUBLE_EQ(rows[0].lo, -5.0);
  EXPECT_DOUBLE_EQ(rows[0].hi, 5.0);
  // a hard motor row (CFM 0) is not one the Newton solver takes: refused, nothing appended
  dJointSetAMotorParam(motor, dParamCFM2, 0.0);
  rows.clear();
  EXPECT_FALSE(JointRows(motor, 0, -1, JointFrame{}, bodies.world, kJointStep, &rows));
  EXPECT_TRUE(rows.empty());
}

TEST(OdeJointRowsTest, WhatIsNotReplicatedIsRefused) {
  TwoBodies bodies;
  bodies.Hinge();
  std::vector<NewtonRow> rows;
  dJointSetHingeParam(bodies.hinge, dParamFMax, 1.0);  // ODE's own hinge motor
  EXPECT_FALSE(
      JointRows(bodies.hinge, 0, 1, TwoBodies::HingeFrame(), bodies.world, kJointStep, &rows));
  dJointSetHingeParam(bodies.hinge, dParamFMax, 0.0);
  dJointSetHingeParam(bodies.hinge, dParamBounce, 0.5);  // a bouncing stop
  EXPECT_FALSE(
      JointRows(bodies.hinge, 0, 1, TwoBodies::HingeFrame(), bodies.world, kJointStep, &rows));
  EXPECT_TRUE(rows.empty());
  dJointID ball = dJointCreateBall(bodies.world, nullptr);  // a joint type OdeRobot never makes
  dJointAttach(ball, bodies.child, bodies.parent);
  EXPECT_FALSE(JointRows(ball, 0, 1, JointFrame{}, bodies.world, kJointStep, &rows));
  EXPECT_TRUE(rows.empty());
}

// a slider along z between the two bodies, as OdeRobot records it (both bodies unrotated: the
// relative rotation is the identity, the child's centre 1 m below the parent's)
JointFrame SliderFrameOf(dJointID slider) {
  JointFrame frame;
  frame.offset = Vec3(0.0, 0.0, -1.0);
  frame.axis1 = Vec3::UnitZ();
  dJointSetSliderAxis(slider, 0.0, 0.0, 1.0);
  return frame;
}

TEST(OdeJointRowsTest, ASlidersRowsSeeNoMotionOfBothBodiesTogetherNorASlideAlongItsAxis) {
  TwoBodies bodies;
  dJointID slider = dJointCreateSlider(bodies.world, nullptr);
  dJointAttach(slider, bodies.child, bodies.parent);
  const JointFrame frame = SliderFrameOf(slider);
  std::vector<NewtonRow> rows;
  ASSERT_TRUE(JointRows(slider, 0, 1, frame, bodies.world, kJointStep, &rows));
  ASSERT_EQ(rows.size(), 5u);
  const Vec3 child(0.0, 0.0, -0.5), parent(0.0, 0.0, 0.5);
  for (const NewtonRow& row : rows) {
    EXPECT_NEAR(row.rhs, 0.0, 1e-12);
    EXPECT_NEAR(Seen(row, RigidMotion(child, Vec3(0.3, -0.2, 0.1), Vec3(1.0, 2.0, -0.5)),
                     RigidMotion(parent, Vec3(0.3, -0.2, 0.1), Vec3(1.0, 2.0, -0.5))),
                0.0, 1e-12);
    EXPECT_NEAR(Seen(row, RigidMotion(child, 0.7 * Vec3::UnitZ(), Vec3::Zero()), Vec6::Zero()), 0.0,
                1e-12);
  }
  // pulled off its axis by 1 mm along x, it is pulled back at the world ERP
  dBodySetPosition(bodies.child, 0.001, 0.0, -0.5);
  rows.clear();
  ASSERT_TRUE(JointRows(slider, 0, 1, frame, bodies.world, kJointStep, &rows));
  double pulled = 0.0;
  for (const NewtonRow& row : rows) {
    pulled += row.rhs * Seen(row, RigidMotion(child, Vec3::UnitX(), Vec3::Zero()), Vec6::Zero());
  }
  EXPECT_NEAR(pulled, -0.5 / kJointStep * 0.001,
              1e-9);  // Σ rhs·(J e_x): the rows ask −ERP·gap/h along x
}

TEST(OdeJointRowsTest, ASliderBeyondItsStopAndALinearMotorGetLinearRowsThroughTheMiddle) {
  TwoBodies bodies;
  dJointID slider = dJointCreateSlider(bodies.world, nullptr);
  dJointAttach(slider, bodies.child, bodies.parent);
  const JointFrame frame = SliderFrameOf(slider);
  dJointSetSliderParam(slider, dParamLoStop, -0.1);
  dJointSetSliderParam(slider, dParamHiStop, 0.1);
  dJointSetSliderParam(slider, dParamStopERP, 0.2);
  // 0.15 m down (0.05 m past the low stop), and 0.2 m aside: the centres are not on one line
  // along the axis
  dBodySetPosition(bodies.child, 0.2, 0.0, -0.65);
  std::vector<NewtonRow> rows;
  ASSERT_TRUE(JointRows(slider, 0, 1, frame, bodies.world, kJointStep, &rows));
  ASSERT_EQ(rows.size(), 6u);
  const NewtonRow& stop = rows.back();
  EXPECT_EQ(stop.lo, 0.0);  // pushes the child up only
  EXPECT_EQ(stop.hi, kInf);
  EXPECT_NEAR(stop.rhs, 0.2 / kJointStep * 0.05, 1e-9);
  // equal and opposite forces along the axis at the bodies' middle: the pair turning as one is
  // unseen (forces at the centres would see it, and put a couple on the pair)
  EXPECT_EQ(stop.ja.head<3>(), Vec3::UnitZ());
  EXPECT_EQ(stop.jb.head<3>(), -Vec3::UnitZ());
  const Vec3 child(0.2, 0.0, -0.65), parent(0.0, 0.0, 0.5), omega(0.4, -1.0, 0.3);
  EXPECT_NEAR(
      Seen(stop, RigidMotion(child, Vec3::Zero(), omega), RigidMotion(parent, Vec3::Zero(), omega)),
      0.0, 1e-12);

  dJointID motor = dJointCreateLMotor(bodies.world, nullptr);
  dJointAttach(motor, bodies.child, bodies.parent);
  dJointSetLMotorNumAxes(motor, 2);
  dJointSetLMotorAxis(motor, 0, 1, 0.0, 0.0, 1.0);
  dJointSetLMotorAxis(motor, 1, 1, 0.0, 0.0, 1.0);
  dJointSetLMotorParam(motor, dParamFMax, 40.0);
  dJointSetLMotorParam(motor, dParamVel, -0.25);
  dJointSetLMotorParam(motor, dParamCFM, 0.001);
  rows.clear();
  ASSERT_TRUE(JointRows(motor, 0, 1, frame, bodies.world, kJointStep, &rows));
  ASSERT_EQ(rows.size(), 1u);  // the second axis has no fmax
  EXPECT_EQ(rows[0].ja.head<3>(), Vec3::UnitZ());
  EXPECT_NEAR(Seen(rows[0], RigidMotion(child, Vec3::Zero(), omega),
                   RigidMotion(parent, Vec3::Zero(), omega)),
              0.0, 1e-12);
  EXPECT_DOUBLE_EQ(rows[0].rhs, -0.25);
  EXPECT_DOUBLE_EQ(rows[0].cfm, 0.001);
  EXPECT_DOUBLE_EQ(rows[0].lo, -40.0);
  EXPECT_DOUBLE_EQ(rows[0].hi, 40.0);
}

}  // namespace
}  // namespace lamina::core

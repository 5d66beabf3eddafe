// SPDX-License-Identifier: MIT
// Placing a body on its hinge or slider (joint_projection.h): a child moved rigidly along its
// joint reads the coordinate it was moved by and is placed back exactly; a child off its joint
// is placed with the joint's point shared (or on the slider's line) and its rotation a pure
// twist; the placed velocity moves the joint's point with the parent and turns or slides at the
// rate given.
#include "core/sim/joint_projection.h"

#include <cmath>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace lamina::core {
namespace {

constexpr double kOnJointTolerance = 1e-12;

Eigen::Quaterniond AxisTurn(double angle, const Vec3& axis) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized()));
}

BodyState PosedBody(const Eigen::Quaterniond& orientation, const Vec3& centre) {
  BodyState state;
  state.orientation = orientation;
  state.com_position = centre;
  return state;
}

// a parent turned and moving, and a child hanging from a hinge through `pivot` about `axis`
struct HingeScene {
  Vec3 axis = Vec3(0.2, 1.0, -0.3).normalized();
  Vec3 pivot = Vec3(0.4, -0.1, 1.2);
  BodyState parent = PosedBody(AxisTurn(0.7, Vec3(1, 2, 3)), Vec3(0.1, 0.3, 1.5));
  BodyState child = PosedBody(AxisTurn(-0.4, Vec3(3, -1, 2)), Vec3(0.9, -0.4, 0.8));
  JointPlacement joint = MakeJointPlacement(parent, child, false, axis, pivot);
  HingeScene() {
    parent.linear_velocity = Vec3(0.5, -0.2, 0.1);
    parent.angular_velocity = Vec3(0.3, 0.1, -0.7);
  }
  // the child turned by `angle` about the axis through the pivot (the parent where it was built)
  BodyState Turned(double angle) const {
    BodyState moved = child;
    const Eigen::Quaterniond turn = AxisTurn(angle, axis);
    moved.orientation = turn * child.orientation;
    moved.com_position = pivot + turn * (child.com_position - pivot);
    return moved;
  }
};

TEST(JointProjectionTest, AHingeReadsTheAngleItTurnedBy) {
  const HingeScene c;
  EXPECT_NEAR(JointCoordinate(c.joint, c.parent, c.child), 0.0, kOnJointTolerance);
  for (double angle : {0.3, -1.2, 2.9, -3.0}) {
    EXPECT_NEAR(JointCoordinate(c.joint, c.parent, c.Turned(angle)), angle, kOnJointTolerance)
        << angle;
  }
}

TEST(JointProjectionTest, AChildOnItsHingeIsPlacedWhereItIs) {
  const HingeScene c;
  const BodyState turned = c.Turned(0.8);
  const BodyState placed = PlaceOnJoint(c.joint, c.parent, 0.8, 0.0);
  EXPECT_NEAR((placed.com_position - turned.com_position).norm(), 0.0, kOnJointTolerance);
  EXPECT_NEAR(placed.orientation.angularDistance(turned.orientation), 0.0, kOnJointTolerance);
}

TEST(JointProjectionTest, AChildOffItsHingeGetsTheSharedPointAndAPureTwist) {
  const HingeScene c;
  BodyState off = c.Turned(0.5);
  off.com_position += Vec3(1e-3, -2e-3, 5e-4);
  off.orientation = AxisTurn(2e-3, Vec3(1, 0, 0)) * off.orientation;
  const double angle = JointCoordinate(c.joint, c.parent, off);
  EXPECT_NEAR(angle, 0.5, 1e-2);
  const BodyState placed = PlaceOnJoint(c.joint, c.parent, angle, 0.0);
  // the child's copy of the pivot is where the parent's is
  const Vec3 child_pivot = placed.com_position + placed.orientation * c.joint.child_point;
  const Vec3 parent_pivot = c.parent.com_position + c.parent.orientation * c.joint.parent_point;
  EXPECT_NEAR((child_pivot - parent_pivot).norm(), 0.0, kOnJointTolerance);
  EXPECT_NEAR((parent_pivot - c.pivot).norm(), 0.0, kOnJointTolerance);
  // and it is the built child turned about the axis: it reads the same angle again
  EXPECT_NEAR(JointCoordinate(c.joint, c.parent, placed), angle, kOnJointTolerance);
  EXPECT_NEAR(placed.orientation.angularDistance(c.Turned(angle).orientation), 0.0,
              kOnJointTolerance);
}

TEST(JointProjectionTest, APlacedHingeChildMovesItsPivotWithTheParent) {
  const HingeScene c;
  const double rate = 1.7;
  const BodyState placed = PlaceOnJoint(c.joint, c.parent, 0.4, rate);
  const Vec3 axis = c.parent.orientation * c.joint.axis;
  EXPECT_NEAR((placed.angular_velocity - c.parent.angular_velocity - rate * axis).norm(), 0.0,
              kOnJointTolerance);
  const Vec3 pivot = c.parent.com_position + c.parent.orientation * c.joint.parent_point;
  const Vec3 by_parent =
      c.parent.linear_velocity + c.parent.angular_velocity.cross(pivot - c.parent.com_position);
  const Vec3 by_child =
      placed.linear_velocity + placed.angular_velocity.cross(pivot - placed.com_position);
  EXPECT_NEAR((by_child - by_parent).norm(), 0.0, kOnJointTolerance);
  EXPECT_NEAR(JointRate(c.joint, c.parent, placed), rate, kOnJointTolerance);
}

TEST(JointProjectionTest, ASliderReadsItsTravelAndDropsWhatIsAcross) {
  BodyState parent = PosedBody(AxisTurn(0.4, Vec3(0, 1, 1)), Vec3(1, 2, 3));
  parent.angular_velocity = Vec3(0.2, -0.5, 0.3);
  const BodyState child = PosedBody(AxisTurn(1.1, Vec3(1, -1, 0)), Vec3(1.5, 2.2, 2.4));
  const Vec3 axis = Vec3(1, 1, 0).normalized();
  const JointPlacement joint = MakeJointPlacement(parent, child, true, axis, Vec3::Zero());
  BodyState moved = child;
  moved.com_position += 0.25 * axis + Vec3(0, 0, 1e-3);  // along, and a gap across
  moved.orientation = AxisTurn(1e-3, Vec3::UnitZ()) * moved.orientation;
  const double travel = JointCoordinate(joint, parent, moved);
  EXPECT_NEAR(travel, 0.25, kOnJointTolerance);
  const BodyState placed = PlaceOnJoint(joint, parent, travel, -0.6);
  EXPECT_NEAR((placed.com_position - (child.com_position + 0.25 * axis)).norm(), 0.0,
              kOnJointTolerance);
  EXPECT_NEAR(placed.orientation.angularDistance(child.orientation), 0.0, kOnJointTolerance);
  EXPECT_NEAR((placed.angular_velocity - parent.angular_velocity).norm(), 0.0, kOnJointTolerance);
  EXPECT_NEAR(JointRate(joint, parent, placed), -0.6, kOnJointTolerance);
}

TEST(JointProjectionTest, APendulumOnTheWorldReadsItsSwing) {
  const BodyState world;  // the fixed world: identity, at the origin, at rest
  const Vec3 pivot(0, 0, 2), axis = Vec3::UnitY();
  const BodyState rod = PosedBody(Eigen::Quaterniond::Identity(), Vec3(0, 0, 1.5));
  const JointPlacement joint = MakeJointPlacement(world, rod, false, axis, pivot);
  const double angle = M_PI / 3;
  const BodyState swung = PlaceOnJoint(joint, world, angle, 2.0);
  // turning +60° about +y takes the centre 0.5 m below the pivot to 0.5·(−sin 60°, 0, −cos 60°)
  EXPECT_NEAR(
      (swung.com_position - (pivot + 0.5 * Vec3(-std::sin(angle), 0, -std::cos(angle)))).norm(),
      0.0, kOnJointTolerance);
  EXPECT_NEAR((swung.linear_velocity - 2.0 * axis.cross(swung.com_position - pivot)).norm(), 0.0,
              kOnJointTolerance);
  EXPECT_NEAR(JointCoordinate(joint, world, swung), angle, kOnJointTolerance);
}

TEST(JointProjectionTest, AHingesGapIsHowFarItsTwoAxisPointsAre) {
  const HingeScene c;
  EXPECT_NEAR(JointGap(c.joint, c.parent, c.child), 0.0, kOnJointTolerance);
  EXPECT_NEAR(JointGap(c.joint, c.parent, c.Turned(1.3)), 0.0, kOnJointTolerance);  // a swing
  BodyState pulled = c.Turned(1.3);
  const Vec3 apart(0.03, -0.04, 0.0);  // 5 cm
  pulled.com_position += apart;
  EXPECT_NEAR(JointGap(c.joint, c.parent, pulled), apart.norm(), kOnJointTolerance);
  // the parent carries its copy of the point along
  BodyState carried = c.parent;
  carried.com_position += apart;
  EXPECT_NEAR(JointGap(c.joint, carried, pulled), 0.0, kOnJointTolerance);
}

TEST(JointProjectionTest, ASlidersGapIsWhatIsAcrossItsLine) {
  const BodyState parent = PosedBody(AxisTurn(0.4, Vec3(0, 1, 1)), Vec3(1, 2, 3));
  const BodyState child = PosedBody(AxisTurn(1.1, Vec3(1, -1, 0)), Vec3(1.5, 2.2, 2.4));
  const Vec3 axis = Vec3(1, 1, 0).normalized();
  const JointPlacement joint = MakeJointPlacement(parent, child, true, axis, Vec3::Zero());
  BodyState moved = child;
  moved.com_position += 0.7 * axis + Vec3(0, 0, 0.02);  // travel does not count; across does
  EXPECT_NEAR(JointGap(joint, parent, moved), 0.02, kOnJointTolerance);
  // a fixed joint: a slider along no axis, every offset counts and its coordinate stays 0
  const JointPlacement fixed = MakeFixedPlacement(parent, child);
  EXPECT_NEAR(JointGap(fixed, parent, child), 0.0, kOnJointTolerance);
  EXPECT_NEAR(JointGap(fixed, parent, moved), (0.7 * axis + Vec3(0, 0, 0.02)).norm(),
              kOnJointTolerance);
  EXPECT_EQ(JointCoordinate(fixed, parent, moved), 0.0);
}

TEST(JointProjectionTest, AJointMayOpenByTenPercentOfItsOffsetOrOneCentimetre) {
  EXPECT_DOUBLE_EQ(JointBreakGap(1.0), 0.1);
  EXPECT_DOUBLE_EQ(JointBreakGap(0.05), 0.01);
  EXPECT_DOUBLE_EQ(JointBreakGap(0.0), 0.01);
}

}  // namespace
}  // namespace lamina::core

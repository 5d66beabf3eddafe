// SPDX-License-Identifier: MIT
// The robot joint check of the step guard (core/sim/robot_guard.h): the gap of a joint is how far
// a link's origin is from where its parent puts it (a prismatic joint's slide within its limits
// not counted), a step breaks a robot when some gap grows by more than max(1 cm, 10 % of the
// link's offset), and a joint whose gap is beyond that is open.
#include "core/sim/robot_guard.h"

#include <cmath>

#include <gtest/gtest.h>

namespace lamina::core {
namespace {

// a root on a hinge at (0, 0, 1) and a child 0.5 m along the root's x
RobotDesc TwoLinks(LinkJointAxis child_axis) {
  RobotDesc robot;
  robot.links.resize(2);
  robot.links[0].parent_transform.translation() = Vec3(0, 0, 1);
  robot.links[1].parent = 0;
  robot.links[1].axis_type = child_axis;
  robot.links[1].axis = Vec3::UnitX();
  robot.links[1].parent_transform.translation() = Vec3(0.5, 0, 0);
  return robot;
}

std::vector<Pose> Frames(const Vec3& root, const Vec3& child) {
  std::vector<Pose> frames(2, Pose::Identity());
  frames[0].translation() = root;
  frames[1].translation() = child;
  return frames;
}

TEST(RobotGuardTest, GapIsTheDistanceFromWhereTheParentPutsTheLink) {
  const RobotDesc robot = TwoLinks(LinkJointAxis::kRevolute);
  std::vector<double> gaps;
  RobotJointGaps(robot, Frames(Vec3(0, 0, 1.003), Vec3(0.5, 0.004, 1.003)), {1, 1}, &gaps);
  EXPECT_NEAR(gaps[0], 0.003, 1e-12);  // the root against the world
  EXPECT_NEAR(gaps[1], 0.004, 1e-12);
  RobotJointGaps(robot, Frames(Vec3(0, 0, 1), Vec3(7, 7, 7)), {1, 0}, &gaps);
  EXPECT_EQ(gaps[1], 0.0);  // a link without a frame is not measured
}

TEST(RobotGuardTest, APrismaticSlideIsNotAGap) {
  const RobotDesc robot = TwoLinks(LinkJointAxis::kPrismatic);
  std::vector<double> gaps;
  RobotJointGaps(robot, Frames(Vec3(0, 0, 1), Vec3(0.9, 0.002, 1)), {1, 1}, &gaps);
  EXPECT_NEAR(gaps[1], 0.002, 1e-12);
}

TEST(RobotGuardTest, APrismaticSlidePastItsLimitsOpensItsStop) {
  RobotDesc robot = TwoLinks(LinkJointAxis::kPrismatic);
  robot.links[1].q_min = -0.1;
  robot.links[1].q_max = 0.3;
  std::vector<double> gaps;
  // slid 0.4 m along x from where its parent puts it: 0.1 m past q_max, and 3 mm across
  RobotJointGaps(robot, Frames(Vec3(0, 0, 1), Vec3(0.9, 0.003, 1)), {1, 1}, &gaps);
  EXPECT_NEAR(gaps[1], std::hypot(0.1, 0.003), 1e-12);
  RobotJointGaps(robot, Frames(Vec3(0, 0, 1), Vec3(0.25, 0, 1)), {1, 1}, &gaps);
  EXPECT_NEAR(gaps[1], 0.15, 1e-12);  // at x = 0.25 m, short of q_min's 0.4 m
  RobotJointGaps(robot, Frames(Vec3(0, 0, 1), Vec3(0.8, 0, 1)), {1, 1}, &gaps);
  EXPECT_NEAR(gaps[1], 0.0, 1e-12);  // at q_max
}

TEST(RobotGuardTest, AJointOpenBeyondItsBreakGapIsOpenHoweverSlowlyItOpened) {
  const RobotDesc robot = TwoLinks(LinkJointAxis::kRevolute);
  double largest = 0.0;
  EXPECT_FALSE(RobotJointsOpen(robot, {0.09, 0.049}, &largest));
  EXPECT_DOUBLE_EQ(largest, 0.09);
  EXPECT_TRUE(RobotJointsOpen(robot, {0.0, 0.051}, &largest));
  EXPECT_DOUBLE_EQ(largest, 0.09);
  EXPECT_TRUE(RobotJointsOpen(robot, {0.11, 0.0}));
}

TEST(RobotGuardTest, AStepBreaksARobotWhenAGapGrowsPastItsLimit) {
  const RobotDesc robot = TwoLinks(LinkJointAxis::kRevolute);
  EXPECT_DOUBLE_EQ(JointBreakGap(robot.links[0]), 0.1);   // 10 % of 1 m
  EXPECT_DOUBLE_EQ(JointBreakGap(robot.links[1]), 0.05);  // 10 % of 0.5 m
  EXPECT_FALSE(RobotJointsBroke(robot, {0.0, 0.0}, {0.09, 0.049}));
  EXPECT_TRUE(RobotJointsBroke(robot, {0.0, 0.0}, {0.0, 0.051}));
  EXPECT_FALSE(RobotJointsBroke(robot, {0.0, 0.2}, {0.0, 0.24}));  // open before: its growth
  RobotDesc short_links = robot;
  short_links.links[1].parent_transform.translation() = Vec3(0.02, 0, 0);
  EXPECT_DOUBLE_EQ(JointBreakGap(short_links.links[1]), 0.01);  // the 1 cm floor
}

}  // namespace
}  // namespace lamina::core

// SPDX-License-Identifier: MIT
// The robot joint check of the step guard (core/sim/robot_guard.h): the gap of a joint is how far
// a link's origin is from where its parent puts it (a prismatic joint's slide not counted), and a
// step breaks a robot when some gap grows by more than max(1 cm, 10 % of the link's offset).
#include "core/sim/robot_guard.h"

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

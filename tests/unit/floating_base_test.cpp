// SPDX-License-Identifier: MIT
// Placing a floating base (core/robot/floating_base.h) on Klamp't's ATHLETE, whose virtual
// links are x, y, z then yaw, roll, pitch: the hexagon's frame lands on the target exactly, the
// legs keep their values, and a robot without a floating base has no base links to move.
#include "core/robot/floating_base.h"

#include <gtest/gtest.h>

#include "core/robot/kinematics.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::Pose;
using core::Vec3;

TEST(FloatingBaseTest, AthletesHexagonGoesWhereItIsPut) {
  const auto loaded = test::LoadRobot(test::WorldsPath("klampt/robots/athlete.rob"));
  ASSERT_TRUE(loaded->ok);
  const core::RobotDesc& robot = loaded->robot;
  const std::vector<int> links = core::FloatingBaseLinks(robot);
  ASSERT_EQ(links, (std::vector<int>{0, 1, 2, 3, 4, 5}));
  core::VecX q = core::VecX::Zero(robot.dof());
  q[2] = 0.7;
  q[3] = 0.3;   // yaw
  q[8] = 0.25;  // a knee
  const Pose start = core::LinkTransforms(robot, q)[5];
  Pose target = start;
  target.translation() += Vec3(0.4, -0.2, 0.1);
  target.linear() = core::RotationFromMoment(Vec3(0.1, -0.2, 0.5)) * start.linear();
  const std::optional<core::VecX> placed = core::PlaceFloatingBase(robot, links, q, target);
  ASSERT_TRUE(placed);
  const Pose reached = core::LinkTransforms(robot, *placed)[5];
  EXPECT_LT((reached.translation() - target.translation()).norm(), 1e-9);
  EXPECT_LT(core::MomentFromRotation(target.linear().transpose() * reached.linear()).norm(), 1e-9);
  for (int i = 6; i < robot.dof(); ++i) EXPECT_EQ((*placed)[i], q[i]) << "link " << i;
}

TEST(FloatingBaseTest, AFixedBaseHasNoBaseLinks) {
  const auto loaded = test::LoadRobot(test::WorldsPath("klampt/robots/planar3R.rob"));
  ASSERT_TRUE(loaded->ok);
  EXPECT_TRUE(core::FloatingBaseLinks(loaded->robot).empty());
  EXPECT_FALSE(core::PlaceFloatingBase(loaded->robot, {}, core::VecX::Zero(3), Pose::Identity()));
}

}  // namespace
}  // namespace lamina

// SPDX-License-Identifier: MIT
// Interpolating between configurations: linear per link, spin joints the short way round.
#include "core/control/config_space.h"

#include <gtest/gtest.h>

#include "core/math_types.h"

namespace lamina::core {
namespace {

constexpr double kConfigTol = 1e-12;

// three links: a normal revolute joint, a spin joint (link 1) and a prismatic one
RobotDesc ThreeLinks() {
  RobotDesc robot;
  robot.links.resize(3);
  robot.joints = {
      {JointType::kNormal, 0, -1}, {JointType::kSpin, 1, -1}, {JointType::kNormal, 2, -1}};
  return robot;
}

TEST(ConfigSpaceTest, NormalLinksMoveLinearlyAndSpinJointsTheShortWayRound) {
  const RobotDesc robot = ThreeLinks();
  const VecX a = Vec3(0.0, 3.0, 0.5), b = Vec3(2.0, -3.0, 1.5);
  // the spin joint goes from 3 to -3 through pi: 2pi - 6 = 0.283 rad, not -6 rad
  const VecX d = ConfigDifference(robot, a, b);
  EXPECT_NEAR(d[0], 2.0, kConfigTol);
  EXPECT_NEAR(d[1], 2 * kPi - 6.0, kConfigTol);
  EXPECT_NEAR(d[2], 1.0, kConfigTol);
  const VecX half = InterpolateConfig(robot, a, b, 0.5);
  EXPECT_NEAR(half[0], 1.0, kConfigTol);
  EXPECT_NEAR(half[1], 3.0 + (kPi - 3.0), kConfigTol);  // pi, the seam
  EXPECT_NEAR(half[2], 1.0, kConfigTol);
  // past the seam the spin joint reads wrapped: 3 + 0.75 * 0.283 = 3.212 -> 3.212 - 2pi
  EXPECT_NEAR(InterpolateConfig(robot, a, b, 0.75)[1], 3.0 + 0.75 * (2 * kPi - 6.0) - 2 * kPi,
              kConfigTol);
}

TEST(ConfigSpaceTest, EndsAreTheGivenConfigurations) {
  const RobotDesc robot = ThreeLinks();
  const VecX a = Vec3(-1.0, 0.5, 0.25), b = Vec3(1.0, -0.5, -0.25);
  EXPECT_TRUE(InterpolateConfig(robot, a, b, 0.0).isApprox(a, kConfigTol));
  EXPECT_TRUE(InterpolateConfig(robot, a, b, 1.0).isApprox(b, kConfigTol));
  // without spin joints the difference is b - a exactly
  RobotDesc plain = robot;
  plain.joints[1].type = JointType::kNormal;
  const VecX far = Vec3(0.0, 10.0, 0.0);
  EXPECT_NEAR(ConfigDifference(plain, a, far)[1], 9.5, kConfigTol);
  EXPECT_NEAR(InterpolateConfig(plain, a, far, 0.5)[1], 5.25, kConfigTol);
}

}  // namespace
}  // namespace lamina::core

// SPDX-License-Identifier: MIT
// The joint friction rules of core/sim/friction_rows.h: which form a dry-friction row takes for
// a step, and whether that form gave the bounded row's answer.
#include "core/sim/friction_rows.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace lamina::core {
namespace {

constexpr double kCfm = 1e-9;  // ode_robot.cpp's dry-friction CFM
constexpr double kF = 3.0;     // N·m

TEST(FrictionRowsTest, ForceIsMinusTheRateOverCfm) {
  EXPECT_NEAR(FrictionRowForce(kCfm, 1e-9), -1.0, 1e-12);
  EXPECT_NEAR(FrictionRowForce(kCfm, -2e-9), 2.0, 1e-12);
}

TEST(FrictionRowsTest, HoldingJointsGoUnboundedSlidingOnesBecomeTorques) {
  // half of 3 N·m is 1.5 N·m: a rate below 1.5e-9 rad/s; twice is 6 N·m: above 6e-9 rad/s
  EXPECT_EQ(ChooseFrictionRow(kF, kCfm, 0.0), FrictionRowMode::kUnbounded);
  EXPECT_EQ(ChooseFrictionRow(kF, kCfm, -1.4e-9), FrictionRowMode::kUnbounded);
  EXPECT_EQ(ChooseFrictionRow(kF, kCfm, 1.6e-9), FrictionRowMode::kBounded);
  EXPECT_EQ(ChooseFrictionRow(kF, kCfm, -5.9e-9), FrictionRowMode::kBounded);
  EXPECT_EQ(ChooseFrictionRow(kF, kCfm, 6.1e-9), FrictionRowMode::kExplicit);
  EXPECT_EQ(ChooseFrictionRow(kF, kCfm, -0.3), FrictionRowMode::kExplicit);
  // no bound, an infinite one (viscous friction's implicit damper), no CFM or no rate: as it is
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(ChooseFrictionRow(0.0, kCfm, 1.0), FrictionRowMode::kBounded);
  EXPECT_EQ(ChooseFrictionRow(inf, kCfm, 0.0), FrictionRowMode::kBounded);
  EXPECT_EQ(ChooseFrictionRow(kF, 0.0, 0.0), FrictionRowMode::kBounded);
  EXPECT_EQ(ChooseFrictionRow(kF, kCfm, std::nan("")), FrictionRowMode::kBounded);
}

TEST(FrictionRowsTest, TheTorqueOpposesTheRate) {
  EXPECT_EQ(ExplicitFrictionTorque(FrictionRowMode::kExplicit, kF, 0.5), -kF);
  EXPECT_EQ(ExplicitFrictionTorque(FrictionRowMode::kExplicit, kF, -0.5), kF);
  EXPECT_EQ(ExplicitFrictionTorque(FrictionRowMode::kUnbounded, kF, 0.5), 0.0);
  EXPECT_EQ(ExplicitFrictionTorque(FrictionRowMode::kBounded, kF, 0.5), 0.0);
}

TEST(FrictionRowsTest, AnUnboundedRowHeldWhileItsForceStayedWithinTheBound) {
  const FrictionRowMode mode = FrictionRowMode::kUnbounded;
  EXPECT_TRUE(FrictionGuessHeld(mode, kF, kCfm, 0.0, 2.9e-9));    // 2.9 N·m
  EXPECT_TRUE(FrictionGuessHeld(mode, kF, kCfm, 0.0, -3.0e-9));   // exactly the bound
  EXPECT_FALSE(FrictionGuessHeld(mode, kF, kCfm, 0.0, 3.01e-9));  // it would have slipped
  EXPECT_FALSE(FrictionGuessHeld(mode, kF, kCfm, 0.0, std::nan("")));
}

TEST(FrictionRowsTest, ATorqueHeldWhileTheJointKeptSlidingTheSameWay) {
  const FrictionRowMode mode = FrictionRowMode::kExplicit;
  // the bounded row applies −F whenever the rate after the step is above F·cfm = 3e-9 rad/s
  EXPECT_TRUE(FrictionGuessHeld(mode, kF, kCfm, 0.5, 0.4));
  EXPECT_TRUE(FrictionGuessHeld(mode, kF, kCfm, 0.5, 3.0e-9));
  EXPECT_FALSE(FrictionGuessHeld(mode, kF, kCfm, 0.5, 2.9e-9));  // it would have stuck
  EXPECT_FALSE(FrictionGuessHeld(mode, kF, kCfm, 0.5, -0.1));    // it turned back
  EXPECT_TRUE(FrictionGuessHeld(mode, kF, kCfm, -0.5, -0.4));
  EXPECT_FALSE(FrictionGuessHeld(mode, kF, kCfm, -0.5, 0.1));
  EXPECT_FALSE(FrictionGuessHeld(mode, kF, kCfm, 0.5, std::numeric_limits<double>::infinity()));
  // a bounded row is the LCP's own answer
  EXPECT_TRUE(FrictionGuessHeld(FrictionRowMode::kBounded, kF, kCfm, 0.5, -0.1));
}

TEST(FrictionRowsTest, AMergedRowAppliesTheSumOfTheServoAndFrictionForcesAtEveryRate) {
  // a servo row (target 0.3 rad/s, CFM 2e-3) and a holding friction row (CFM 1e-9)
  const double servo_cfm = 2e-3, friction_cfm = 1e-9, target = 0.3;
  const MergedRow merged = MergeServoAndFrictionRows(target, servo_cfm, friction_cfm);
  for (const double rate : {-1.0, -1e-6, 0.0, 3e-10, 1e-7, 0.3, 2.0}) {
    const double sum = (target - rate) / servo_cfm + (0.0 - rate) / friction_cfm;
    const double one = (merged.velocity - rate) / merged.cfm;
    EXPECT_NEAR(one, sum, 1e-12 * std::max(1.0, std::abs(sum))) << rate;
  }
  // a rigid servo (CFM 0) keeps its target whatever friction adds
  const MergedRow rigid = MergeServoAndFrictionRows(target, 0.0, friction_cfm);
  EXPECT_EQ(rigid.velocity, target);
  EXPECT_EQ(rigid.cfm, 0.0);
}

}  // namespace
}  // namespace lamina::core

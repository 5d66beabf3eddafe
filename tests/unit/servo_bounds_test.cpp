// SPDX-License-Identifier: MIT
// The servo-row rules of core/sim/servo_bounds.h: the force a motor row applied, from ODE's row
// law J v' = v_target - cfm·λ, and when a row may go unbounded.
#include "core/sim/servo_bounds.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace lamina::core {
namespace {

// kP 1000 N·m/rad, kD 10 N·m·s/rad at 1 ms: stiffness kP·h + kD = 11, cfm 1/11; limit 3 N·m
ServoMotorCommand Motor(double velocity) {
  ServoMotorCommand motor;
  motor.link = 0;
  motor.velocity = velocity;
  motor.cfm = 1.0 / 11.0;
  motor.fmax = 3.0;
  return motor;
}

TEST(ServoBoundsTest, RowForceIsTheRateShortfallOverCfm) {
  // the row wanted 0.2 rad/s and the joint ended at 0.1: λ = 0.1 · 11 = 1.1 N·m
  EXPECT_NEAR(ServoRowForce(Motor(0.2), 0.1), 1.1, 1e-12);
  EXPECT_NEAR(ServoRowForce(Motor(0.2), 0.3), -1.1, 1e-12);
  EXPECT_EQ(ServoRowForce(Motor(0.2), 0.2), 0.0);
}

TEST(ServoBoundsTest, ARowGoesUnboundedWellInsideItsLimit) {
  // half of 3 N·m is 1.5 N·m: a shortfall below 1.5 / 11 rad/s
  EXPECT_TRUE(ServoMayGoUnbounded(Motor(0.13), 0.0));   // 1.43 N·m
  EXPECT_FALSE(ServoMayGoUnbounded(Motor(0.14), 0.0));  // 1.54 N·m
  EXPECT_FALSE(ServoMayGoUnbounded(Motor(-0.14), 0.0));
  // an unlimited servo is unbounded already; a motor that is off or has no cfm stays as it is
  ServoMotorCommand unlimited = Motor(0.0);
  unlimited.fmax = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(ServoMayGoUnbounded(unlimited, 0.0));
  ServoMotorCommand off = Motor(0.0);
  off.fmax = 0.0;
  EXPECT_FALSE(ServoMayGoUnbounded(off, 0.0));
  ServoMotorCommand rigid = Motor(0.0);
  rigid.cfm = 0.0;
  EXPECT_FALSE(ServoMayGoUnbounded(rigid, 0.0));
}

TEST(ServoBoundsTest, TheForceAfterTheStepIsCheckedAgainstTheLimit) {
  // 3 / 11 rad/s of shortfall is exactly the limit (within rounding); beyond it is over
  EXPECT_TRUE(ServoForceWithinBound(Motor(0.0), 3.0 / 11.0));
  EXPECT_TRUE(ServoForceWithinBound(Motor(0.0), -3.0 / 11.0));
  EXPECT_FALSE(ServoForceWithinBound(Motor(0.0), 3.001 / 11.0));
  EXPECT_FALSE(ServoForceWithinBound(Motor(0.0), std::nan("")));
}

}  // namespace
}  // namespace lamina::core

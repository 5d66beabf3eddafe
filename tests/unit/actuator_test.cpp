// SPDX-License-Identifier: MIT
// Actuator law: PID numbers, torque clamping (limits read live), anti-windup bound, continuous
// joint wrap-around, torque mode, off and locked-velocity modes.
#include "core/control/actuator.h"

#include <cmath>

#include <gtest/gtest.h>

namespace lamina::core {
namespace {

DriverDesc Driver(double torque_limit) {
  DriverDesc driver;
  driver.q_min = -1;
  driver.q_max = 1;
  driver.torque_min = -torque_limit;
  driver.torque_max = torque_limit;
  driver.servo_p = 10;
  driver.servo_i = 2;
  driver.servo_d = 3;
  return driver;
}

ActuatorState PidState() {
  ActuatorState state = InitialActuatorState(Driver(100), true, 0.0);
  state.q_des = 1.0;
  state.dq_des = 0.5;
  state.i_term = 0.25;
  state.torque = 1.0;
  return state;
}

TEST(ActuatorTest, InitialStateHoldsTheValue) {
  const ActuatorState state = InitialActuatorState(Driver(100), true, 0.3);
  EXPECT_EQ(state.mode, ActuatorMode::kPid);
  EXPECT_EQ(state.q_des, 0.3);
  EXPECT_EQ(state.dq_des, 0);
  EXPECT_EQ(state.i_term, 0);
  EXPECT_FALSE(state.relative_encoding);
}

TEST(ActuatorTest, PidLawNumbers) {
  // 10·0.2 + 3·(0.5 − 0.1) + 2·0.25 + 1 = 4.7
  EXPECT_NEAR(ActuatorEffort(PidState(), Driver(100), 0.8, 0.1), 4.7, 1e-12);
}

TEST(ActuatorTest, GainsAreTheDriversReadLive) {
  DriverDesc driver = Driver(100);
  driver.servo_p = 20;  // 20·0.2 + 3·(0.5 − 0.1) + 2·0.25 + 1 = 6.7
  EXPECT_NEAR(ActuatorEffort(PidState(), driver, 0.8, 0.1), 6.7, 1e-12);
}

TEST(ActuatorTest, PidIsClampedToTheDriverLimitsReadLive) {
  DriverDesc driver = Driver(3);
  EXPECT_EQ(ActuatorEffort(PidState(), driver, 0.8, 0.1), 3);
  driver.torque_min = -1;
  EXPECT_EQ(ActuatorEffort(PidState(), driver, 3.0, 0.0), -1);  // 10·(−2) + 1.5 + 0.5 + 1
  driver.torque_max = 10;
  EXPECT_NEAR(ActuatorEffort(PidState(), driver, 0.8, 0.1), 4.7, 1e-12);
}

TEST(ActuatorTest, IntegralAccumulatesErrorTimesStep) {
  ActuatorState state = PidState();
  IntegrateActuator(Driver(100), 0.8, 0.01, &state);
  EXPECT_NEAR(state.i_term, 0.25 + 0.2 * 0.01, 1e-15);
}

TEST(ActuatorTest, AntiWindupBoundsTheIntegralEffort) {
  DriverDesc driver = Driver(5);
  driver.torque_min = -4;
  driver.servo_i = 10;
  ActuatorState state = InitialActuatorState(driver, true, 0.0);
  state.q_des = 1;
  for (int i = 0; i < 1000; ++i) IntegrateActuator(driver, 0.0, 0.01, &state);
  EXPECT_NEAR(driver.servo_i * state.i_term, 5, 1e-12);
  state.q_des = -1;
  for (int i = 0; i < 1000; ++i) IntegrateActuator(driver, 0.0, 0.01, &state);
  EXPECT_NEAR(driver.servo_i * state.i_term, -4, 1e-12);
}

TEST(ActuatorTest, ContinuousDriversAreDetectedByRange) {
  DriverDesc driver = Driver(1);
  EXPECT_FALSE(IsContinuousDriver(driver, true));
  driver.q_min = -kInf;
  driver.q_max = kInf;
  EXPECT_TRUE(IsContinuousDriver(driver, true));
  EXPECT_FALSE(IsContinuousDriver(driver, false));  // prismatic
  driver.q_min = -kPi;
  driver.q_max = kPi;
  EXPECT_TRUE(IsContinuousDriver(driver, true));
  driver.type = DriverType::kAffine;
  EXPECT_FALSE(IsContinuousDriver(driver, true));
}

TEST(ActuatorTest, ContinuousJointErrorWrapsAround) {
  DriverDesc driver = Driver(1000);
  driver.q_min = -kInf;
  driver.q_max = kInf;
  ActuatorState state = InitialActuatorState(driver, true, 0.0);
  ASSERT_TRUE(state.relative_encoding);
  state.q_des = 3.1;
  const double expected = 6.2 - 2 * kPi;  // ≈ −0.0832
  EXPECT_NEAR(PositionError(state, -3.1), expected, 1e-12);
  EXPECT_NEAR(ActuatorEffort(state, driver, -3.1, 0.0), 10 * expected, 1e-10);
  IntegrateActuator(driver, -3.1, 0.5, &state);
  EXPECT_NEAR(state.i_term, 0.5 * expected, 1e-12);
  state.relative_encoding = false;
  EXPECT_NEAR(PositionError(state, -3.1), 6.2, 1e-12);
}

TEST(ActuatorTest, TorqueModeIsClamped) {
  DriverDesc driver = Driver(2);
  ActuatorState state;
  state.mode = ActuatorMode::kTorque;
  state.torque = 1.5;
  EXPECT_EQ(ActuatorEffort(state, driver, 0.3, 7.0), 1.5);
  state.torque = -7;
  EXPECT_EQ(ActuatorEffort(state, driver, 0.3, 7.0), -2);
  state.i_term = 0.1;
  IntegrateActuator(driver, 0.3, 0.01, &state);  // no integral outside PID mode
  EXPECT_EQ(state.i_term, 0.1);
}

TEST(ActuatorTest, OffAndLockedVelocityGiveNoEffort) {
  ActuatorState state = PidState();
  state.mode = ActuatorMode::kOff;
  EXPECT_EQ(ActuatorEffort(state, Driver(100), 0.8, 0.1), 0);
  state.mode = ActuatorMode::kLockedVelocity;
  EXPECT_EQ(ActuatorEffort(state, Driver(100), 0.8, 0.1), 0);
  IntegrateActuator(Driver(100), 0.8, 0.1, &state);
  EXPECT_NEAR(state.q_des, 1.0 + 0.5 * 0.1, 1e-15);
}

}  // namespace
}  // namespace lamina::core

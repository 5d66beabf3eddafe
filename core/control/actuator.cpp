// SPDX-License-Identifier: MIT
// The actuator law of actuator.h: PID with feed-forward, torque clamping, anti-windup.
#include "core/control/actuator.h"

#include <algorithm>
#include <cmath>

#include "core/control/angles.h"

namespace lamina::core {
namespace {

double Clamp(double value, double low, double high) {
  return std::max(low, std::min(high, value));
}

// Keeps ki·i_term within [low, high]; nothing to bound while ki is 0.
double AntiWindup(double i_term, double ki, double low, double high) {
  if (ki <= 0) return i_term;
  if (ki * i_term > high) return high / ki;
  if (ki * i_term < low) return low / ki;
  return i_term;
}

}  // namespace

bool IsContinuousDriver(const DriverDesc& driver, bool revolute) {
  if (driver.type != DriverType::kNormal || !revolute) return false;
  const double range = driver.q_max - driver.q_min;
  return !std::isfinite(range) || range >= 2 * kPi;
}

ActuatorState InitialActuatorState(const DriverDesc& driver, bool revolute, double q) {
  ActuatorState state;
  state.mode = ActuatorMode::kPid;
  state.q_des = q;
  state.relative_encoding = IsContinuousDriver(driver, revolute);
  return state;
}

double PositionError(const ActuatorState& state, double q) {
  return state.relative_encoding ? AngleDiff(state.q_des, q) : state.q_des - q;
}

double ActuatorEffort(const ActuatorState& state, const DriverDesc& driver, double q, double dq) {
  switch (state.mode) {
    case ActuatorMode::kTorque:
      return Clamp(state.torque, driver.torque_min, driver.torque_max);
    case ActuatorMode::kPid: {
      const double effort = driver.servo_p * PositionError(state, q) +
                            driver.servo_d * (state.dq_des - dq) + driver.servo_i * state.i_term +
                            state.torque;
      return Clamp(effort, driver.torque_min, driver.torque_max);
    }
    case ActuatorMode::kOff:
    case ActuatorMode::kLockedVelocity:
      break;
  }
  return 0;
}

void IntegrateActuator(const DriverDesc& driver, double q, double h, ActuatorState* state) {
  if (state->mode == ActuatorMode::kPid) {
    state->i_term += PositionError(*state, q) * h;
    state->i_term = AntiWindup(state->i_term, driver.servo_i, driver.torque_min, driver.torque_max);
  } else if (state->mode == ActuatorMode::kLockedVelocity) {
    state->q_des += state->dq_des * h;
  }
}

}  // namespace lamina::core
